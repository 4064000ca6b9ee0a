/* SPDX-License-Identifier: GPL-2.0-or-later */
/* logic.comp - logic(9): and / or / xor (odd parity) of up to 16 inputs; personality =
 * number of inputs + 0x100 (and) + 0x200 (or) + 0x400 (xor). */
component logic "EMC2 HAL component providing experimental logic functions";
description """Experimental general 'logic function' component.  Can perform 'and', 'or' and
'xor' of up to 16 inputs.  Determine the proper value for 'personality' by adding:

- The number of input pins, usually from 2 to 16
- 256 (0x100) if the 'and' output is desired
- 512 (0x200) if the 'or' output is desired
- 1024 (0x400) if the 'xor' (exclusive or) output is desired""";
pin in bit in-##[16 : personality & 0xff];
pin out bit and if personality & 0x100;
pin out bit or if personality & 0x200;
pin out bit xor if personality & 0x400;
function _ nofp;
option personality yes;
option extra_setup yes;
license "GPL";
;;
EXTRA_SETUP()
{
	int inputs = personality & 0xff;

	if (inputs < 1 || inputs > 16) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"logic: %s: personality 0x%x asks for %d inputs, must be 1..16\n",
				prefix, (unsigned)personality, inputs);
		return -EINVAL;
	}
	if (!(personality & 0x700)) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"logic: %s: personality 0x%x selects no output; add 0x100 (and), 0x200 (or) or 0x400 (xor)\n",
				prefix, (unsigned)personality);
		return -EINVAL;
	}
	return 0;
}

FUNCTION(_)
{
	int i, inputs = personality & 0xff;
	bool all = true, any = false, odd = false;

	for (i = 0; i < inputs; i++) {
		if (in(i)) {
			any = true;
			odd = !odd;
		} else {
			all = false;
		}
	}
	if (personality & 0x100)
		and = all;
	if (personality & 0x200)
		or = any;
	if (personality & 0x400)
		xor = odd;
}
