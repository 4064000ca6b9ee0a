#!/bin/sh
# The display: sees the whole machine up (components in start-up order, HALCMD
# lines applied, the thread running), then quits with status 3.
{
	echo "display args: $*" | sed "s|$PWD|.|g"
	echo "INI_FILE_NAME=$INI_FILE_NAME" | sed "s|$PWD|.|g"
	halcmd show comp | sed -e 's/  *[0-9][0-9]*  *ready$/ PID ready/' -e 's/ *$//'
	halcmd getp and2.0.in0
	halcmd show sig both | sed -n 's/ *$//;/both/p'
	halcmd show thread servo | grep -c 'and2.0'
} > display.out 2>&1
exit 3
