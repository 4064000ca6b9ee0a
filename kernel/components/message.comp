/* SPDX-License-Identifier: GPL-2.0-or-later */
/* message.comp - message(9): print one configured text (messages=) when trigger becomes active. */
component message "Display a message";
description """Allows HAL pins to trigger a message.  Example hal commands:

loadrt message names=oillow,oilpressure,inverterfail messages="Slideway oil low,No oil pressure,Spindle inverter fault"
addf oillow servo-thread
addf oilpressure servo-thread
addf inverterfail servo-thread

setp oillow.edge 0 #this pin should be active low
net no-oil classicladder.0.out-21 oillow.trigger
net no-pressure classicladder.0.out-22 oilpressure.trigger
net no-inverter classicladder.0.out-23 inverterfail.trigger

When any pin goes active, the corresponding message will be displayed.""";
pin in bit trigger = FALSE "signal that triggers the message";
pin in bit force = FALSE "A FALSE->TRUE transition forces the message to be displayed again if the trigger is active";
param rw bit edge = TRUE """Selects the desired edge: TRUE means the message shows when trigger
becomes TRUE, FALSE when it becomes FALSE (an active-low trigger, as in the example)""";
modparam dummy messages """The messages to display.  These should be listed, comma-delimited,
inside a single set of quotes.  See the "Description" section for an example.  If there are more
messages than "count" or "names" then the excess will be ignored.  If there are fewer messages
than "count" or "names" then an error will be raised and the component will not load.""";
variable char *text;		/* this instance's entry of messages= */
variable int last_trigger;
variable int last_force;
variable int started;		/* the first period only learns the trigger level */
function _ nofp "Display a message";
option extra_setup yes;
license "GPL v2";
;;
#define MESSAGE_MAX 64	/* as many as comp's count=/names= allow */
static char *messages[MESSAGE_MAX];
RTAPI_MP_ARRAY_STRING(messages, MESSAGE_MAX, "The messages to display, comma-delimited");

/* Instances are set up one after another, in order, at load time: the n-th one set up takes
 * the n-th message. Init code only; realtime code never touches it. */
static int next_message;

EXTRA_SETUP()
{
	int n = next_message++;

	if (n >= MESSAGE_MAX || !messages[n] || !messages[n][0]) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"message: %s has no message: messages= gives %d, one per instance is needed\n",
				prefix, n);
		return -EINVAL;
	}
	text = messages[n];
	return 0;
}

FUNCTION(_)
{
	bool active = !trigger == !edge;
	bool became_active = !started ? false : !last_trigger != !trigger && active;

	/* a rising edge of force repeats the message while the trigger is active */
	if (became_active || (active && force && !last_force && started))
		rtapi_print_msg(RTAPI_MSG_ERR, "%s\n", text);
	started = 1;
	last_trigger = trigger;
	last_force = force;
}
