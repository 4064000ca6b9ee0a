# pcl720 load refusals (no card, bad address, a card twice, a range straddling a
# card) print their message and leave nothing loaded; then a good load works.
halrun -k -f errors.hal
echo "exit $?"
