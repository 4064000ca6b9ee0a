/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_print_kmod.c - messages through printk (rtapi_print(3rtapi)), the FPU-safe
 * entry to the shared formatter, and the message ring behind /proc/rtapi/messages,
 * in the kernel flavor. The variadic entry points live in rtapi_print_entry_kmod.c:
 * they must be compiled with SSE so that va_start sees double arguments. */
#include <linux/module.h>
#include <linux/kernel.h>
#include <linux/printk.h>
#include <linux/seq_file.h>
#include <linux/spinlock.h>
#include <asm/fpu/api.h>
#include "rtapi_kmod.h"

/* The last RING_LINES messages, numbered, so that halcmd can show the message of a
 * component whose rtapi_app_main failed (insmod only reports the errno). Realtime
 * tasks may print too, hence a raw spinlock and no allocation. */
#define RING_LINES 64
#define RING_TEXT 200

struct ring_line {
	u64 seq;
	int level;
	char text[RING_TEXT];
};

static struct ring_line ring[RING_LINES];
static u64 ring_next_seq = 1;	/* the number the next message gets */
static DEFINE_RAW_SPINLOCK(ring_lock);

static int msg_level = RTAPI_MSG_ERR;
module_param(msg_level, int, 0644);
MODULE_PARM_DESC(msg_level, "RTAPI message level, 0 (none) .. 5 (all), default 1 (errors)");

static rtapi_msg_handler_t msg_handler;

/* rtapi_format.c is compiled with SSE enabled and its entry points renamed to these
 * (see kernel/Kbuild): gcc may use SSE registers anywhere in that file, so every
 * call must sit inside a kernel FPU section. */
int rtapi_vsnprintf_fpu(char *buf, unsigned long int size, const char *fmt, va_list ap);

int rtapi_vsnprintf(char *buf, unsigned long int size, const char *fmt, va_list ap)
{
	int n;

	/* false inside a kernel FPU section already (a uses_fp task's cycle): the
	 * registers are ours there, and FPU sections must not nest. */
	if (!irq_fpu_usable())
		return rtapi_vsnprintf_fpu(buf, size, fmt, ap);
	kernel_fpu_begin();
	n = rtapi_vsnprintf_fpu(buf, size, fmt, ap);
	kernel_fpu_end();
	return n;
}
EXPORT_SYMBOL(rtapi_vsnprintf);

static void default_handler(msg_level_t level, const char *msg)
{
	switch (level) {
	case RTAPI_MSG_ERR: printk(KERN_ERR "%s", msg); break;
	case RTAPI_MSG_WARN: printk(KERN_WARNING "%s", msg); break;
	case RTAPI_MSG_INFO: printk(KERN_INFO "%s", msg); break;
	default: printk(KERN_DEBUG "%s", msg); break;
	}
}

static void ring_add(int level, const char *msg)
{
	struct ring_line *l;
	unsigned long flags;
	int i;

	raw_spin_lock_irqsave(&ring_lock, flags);
	l = &ring[ring_next_seq % RING_LINES];
	l->seq = ring_next_seq++;
	l->level = level;
	/* one line per message: newlines inside become blanks, the final one goes */
	for (i = 0; msg[i] && i < RING_TEXT - 1; i++)
		l->text[i] = msg[i] == '\n' ? ' ' : msg[i];
	while (i > 0 && l->text[i - 1] == ' ' && msg[i - 1] == '\n')
		i--;
	l->text[i] = '\0';
	raw_spin_unlock_irqrestore(&ring_lock, flags);
}

void rtapi_message_show(struct seq_file *m)
{
	struct ring_line copy;
	unsigned long flags;
	u64 seq, first;

	raw_spin_lock_irqsave(&ring_lock, flags);
	seq = ring_next_seq;
	raw_spin_unlock_irqrestore(&ring_lock, flags);
	first = seq > RING_LINES ? seq - RING_LINES : 1;
	seq_printf(m, "next %llu\n", seq);
	for (; first < seq; first++) {
		raw_spin_lock_irqsave(&ring_lock, flags);
		copy = ring[first % RING_LINES];
		raw_spin_unlock_irqrestore(&ring_lock, flags);
		if (copy.seq == first)	/* else overwritten meanwhile */
			seq_printf(m, "%llu %d %s\n", copy.seq, copy.level, copy.text);
	}
}

/* rtapi_print and rtapi_print_msg (rtapi_print_entry_kmod.c) end here. */
void rtapi_vprint_msg_kmod(int level, const char *fmt, va_list ap)
{
	char buf[256];	/* printk truncates long lines anyway */
	rtapi_msg_handler_t h;

	if (level != RTAPI_MSG_ALL &&
	    (level <= RTAPI_MSG_NONE || level > READ_ONCE(msg_level)))
		return;
	h = READ_ONCE(msg_handler);
	rtapi_vsnprintf(buf, sizeof(buf), fmt, ap);
	ring_add(level, buf);
	(h ? h : default_handler)(level, buf);
}

int rtapi_set_msg_level(int level)
{
	if (level < RTAPI_MSG_NONE || level > RTAPI_MSG_ALL)
		return -EINVAL;
	WRITE_ONCE(msg_level, level);
	return 0;
}
EXPORT_SYMBOL(rtapi_set_msg_level);

int rtapi_get_msg_level(void)
{
	return READ_ONCE(msg_level);
}
EXPORT_SYMBOL(rtapi_get_msg_level);

void rtapi_set_msg_handler(rtapi_msg_handler_t handler)
{
	WRITE_ONCE(msg_handler, handler);
}
EXPORT_SYMBOL(rtapi_set_msg_handler);

rtapi_msg_handler_t rtapi_get_msg_handler(void)
{
	return READ_ONCE(msg_handler);
}
EXPORT_SYMBOL(rtapi_get_msg_handler);
