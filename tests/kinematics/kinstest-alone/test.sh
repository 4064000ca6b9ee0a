# kinstest needs a kinematics module loaded first; without one it is refused.
halcmd loadrt kinstest
echo "kinstest alone status $? components $(halcmd -s show comp | grep -c .)"
halcmd loadrt rotatekins && halcmd loadrt kinstest
echo "kinstest after rotatekins status $? components $(halcmd -s show comp | grep -c .)"
halcmd unloadrt kinstest && halcmd unloadrt rotatekins
echo "unloaded status $? components $(halcmd -s show comp | grep -c .)"
halrun -U
