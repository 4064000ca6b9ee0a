# The instance number differs from run to run.
{
halcmd loadrt and2
echo "halcmd loadrt: $?"
halrun -f /dev/null
echo "halrun while running: $?"
halrun -U
echo "halrun -U: $?"
halrun -f /dev/null
echo "halrun after -U: $?"
halrun -U -k
echo "halrun -U -k: $?"
halrun -f .hal -I nothing
echo "halrun misplaced -I: $?"
} 2>&1 | sed 's/RTAPI_INSTANCE=[0-9]*/RTAPI_INSTANCE=N/'
