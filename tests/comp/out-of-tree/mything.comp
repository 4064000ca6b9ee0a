// A component outside the tree that uses most of the comp language.
component mything "A test of the comp language";
pin in float in0 = 1.5 "first input";
pin in float in1;
pin out float sum "(in0 + in1) * gain + last";
pin out bit out-#[4] "bit i of sel";
pin in s32 sel = -2;
pin io u32 count_io;
pin out s32 extra if personality & 1 "personality, when bit 0 of it is set";
pin out float arr-##[8 : personality >> 4] "personality >> 4 of them";
param rw float gain = 2.0;
param r s32 calls;
param rw bit flag = TRUE;
variable double last = 0.25;
variable int hist[3];
option personality yes;
option extra_setup yes;
option extra_cleanup yes;
function add "sum = (in0 + in1) * gain + last";
function set_bits nofp;
license "GPL";
author "the comp tests";
;;
FUNCTION(add)
{
	sum = (in0 + in1) * gain + last;
	calls++;
}

FUNCTION(set_bits)
{
	int i;

	for (i = 0; i < 4; i++)
		out(i) = (sel >> i) & 1;
	count_io += 1;
	hist[0] = count_io;
	if (personality & 1)
		extra = personality;
	for (i = 0; i < (personality >> 4); i++)
		arr(i) = i * 0.5;
}

EXTRA_SETUP()
{
	calls = 100 + extra_arg;
	return 0;
}

EXTRA_CLEANUP()
{
}
