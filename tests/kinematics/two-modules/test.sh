# Only one kinematics module at a time: a second is refused while the first is
# loaded (its functions would be ambiguous), and loads once the first is gone.
halcmd loadrt trivkins
echo "trivkins status $?"
halcmd loadrt gantrykins
echo "gantrykins status $?"
halcmd -s show comp | awk '{ print "loaded", $3 }'
halcmd unloadrt trivkins
halcmd loadrt gantrykins
echo "gantrykins again status $?"
halcmd -s show comp | awk '{ print "loaded", $3 }'
halrun -U
