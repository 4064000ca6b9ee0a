# A halcmd that starts rtapi_app must not leave its stderr pipe open there: "| cat"
# returns as soon as halcmd does, not when the HAL is torn down.
timeout 20 sh -c 'halcmd loadrt and2 2>&1 | cat; echo "pipe closed"'
echo "status $?"
halcmd list comp
halrun -U
