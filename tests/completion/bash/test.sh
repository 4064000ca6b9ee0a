# Runs the completion function as bash would for a command line and prints the
# candidates, against a HAL with two and2 gates, a thread and a signal.
halcmd -f <<'HAL' || exit 1
loadrt threads name1=fast period1=1000000
loadrt and2 count=2
net gate and2.0.out => and2.1.in0
HAL
comp=$(cd ../../.. && pwd)/user/halcmd/bash-completion/halcmd
complete_line() {	# complete_line WORD... : the last word is the one completed
	bash -c '
		. "$0"
		COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1))
		case $1 in halcmd) _halcmd ;; halrun) _halrun ;; esac
		printf "%s\n" "${COMPREPLY[@]}" | sort | tr "\n" " "; echo' "$comp" "$@"
}
echo "halcmd lo:        $(complete_line halcmd lo)"
echo "halcmd -s sh:     $(complete_line halcmd -s sh)"
echo "halcmd -:         $(complete_line halcmd --fl)"
echo "setp and2.0.:     $(complete_line halcmd setp and2.0.)"
echo "net gate:         $(complete_line halcmd net g)"
echo "net gate pin:     $(complete_line halcmd net gate and2.1.in)"
echo "addf:             $(complete_line halcmd addf and)"
echo "addf thread:      $(complete_line halcmd addf and2.0 f)"
echo "loadrt and:       $(complete_line halcmd loadrt and)"
echo "unloadrt:         $(complete_line halcmd unloadrt '')"
echo "show kinds:       $(complete_line halcmd show p)"
echo "list funct:       $(complete_line halcmd list funct '')"
echo "newsig type:      $(complete_line halcmd newsig s f)"
echo "lock:             $(complete_line halcmd lock c)"
echo "halrun -:         $(complete_line halrun -)"
halrun -U
