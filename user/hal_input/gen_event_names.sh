#!/bin/sh
# gen_event_names.sh HEADER OUT - the evdev code names of linux/input-event-codes.h as
# a C table {type, code, "pin-name"}: KEY_LEFTSHIFT -> "key-leftshift", BTN_LEFT ->
# "btn-left", ABS_HAT0X -> "abs-hat0x", LED_CAPSL -> "led-capsl". The _MAX/_CNT/
# _RESERVED markers are left out; of aliases (two names, one code) the lookup takes the first.
set -e
awk '
/^#define (KEY|BTN|ABS|REL|LED)_[A-Z0-9_]+[ \t]+(0x[0-9a-fA-F]+|[0-9]+)([ \t]|$)/ {
	name = $2; val = $3
	if (name ~ /_(MAX|CNT|RESERVED)$/ || name ~ /^KEY_MIN_INTERESTING$/) next
	split(name, part, "_"); prefix = part[1]
	type = (prefix == "KEY" || prefix == "BTN") ? "EV_KEY" : "EV_" prefix
	pin = tolower(name); gsub(/_/, "-", pin)
	printf "\t{%s, %s, \"%s\"},\n", type, name, pin
}' "$1" >"$2.tmp"
mv "$2.tmp" "$2"
