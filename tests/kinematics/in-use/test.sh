# The kernel refuses rmmod of a module whose exports another module uses; the
# simulated flavor must refuse too, or kinstest would call unmapped code.
halcmd loadrt trivkins || exit 1
halcmd loadrt kinstest joints=3 || exit 1
halcmd unloadrt trivkins
echo "unload while used status $?"
halcmd -s show comp | awk '{ print "loaded", $3 }'
halcmd unloadrt kinstest
echo "kinstest unload status $?"
halcmd unloadrt trivkins
echo "trivkins unload status $?"
halcmd -s show comp | awk '{ print "after", $3 }'
# motmod holds the kinematics module it found at load the same way
halcmd loadrt trivkins || exit 1
halcmd loadrt motmod num_joints=3 || exit 1
halcmd unloadrt trivkins
echo "unload under motmod status $?"
halcmd -s show comp | awk '{ print "motmod loaded", $3 }'
halcmd unloadrt motmod
echo "motmod unload status $?"
halcmd unloadrt trivkins
echo "trivkins unload after motmod status $?"
halcmd -s show comp | awk '{ print "after motmod", $3 }'
halrun -U
