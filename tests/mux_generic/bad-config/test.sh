# Each bad config is refused (halcmd exits 1) with one line naming the entry.
halcmd loadrt mux_generic config=bb4,xf2 ; echo "status $?"
halcmd loadrt mux_generic config=bb0 ; echo "status $?"
halcmd loadrt mux_generic config=ff1025 ; echo "status $?"
halcmd loadrt mux_generic config=ffx ; echo "status $?"
halcmd loadrt mux_generic ; echo "status $?"
echo "left: $(halcmd list comp | tr ' ' '\n' | grep -c mux_generic)"
halrun -U
