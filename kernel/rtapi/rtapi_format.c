/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_format.c - rtapi_vsnprintf (rtapi_snprintf(3rtapi)) for both flavors: plain C,
 * no libc, so the kernel build prints %f/%e/%g exactly as userspace does. Conversions:
 * d i u x X o c s p % f F e E g G with flags - + space # 0, width and precision (also *),
 * length modifiers hh h l ll z j t. Doubles are converted exactly from their bits
 * (big-integer arithmetic) and rounded half-to-even as glibc does; precisions beyond
 * FMT_DIGITS significant digits print zeros there. Only fmt_double() touches a
 * floating-point value; the kernel build still compiles this whole file with SSE and
 * calls it inside an FPU section (rtapi_print_kmod.c). */
#include "rtapi.h"

#define FMT_DIGITS	400	/* significant decimal digits kept for a double */
#define FMT_WORDS	36	/* 32-bit words of the big numbers: 1024+53 bits + slack */

struct fmt_out {
	char *buf;
	unsigned long size;
	unsigned long len;	/* characters produced, also those that did not fit */
};

struct fmt_spec {
	int left, plus, space, alt, zero;	/* flags - + space # 0 */
	int width;
	int prec;		/* -1: not given */
	char conv;
};

/* Decimal digits of a double: value = 0.d[0]d[1]... * 10^(exp10 + 1). */
struct fmt_decimal {
	unsigned char d[FMT_DIGITS];	/* digit values 0..9 */
	int n;				/* digits stored; zero when the value is 0 */
	int exp10;			/* power of ten of d[0] */
};

static void put(struct fmt_out *o, char c)
{
	if (o->len + 1 < o->size)
		o->buf[o->len] = c;
	o->len++;
}

static void put_rep(struct fmt_out *o, char c, int n)
{
	while (n-- > 0)
		put(o, c);
}

static void put_str(struct fmt_out *o, const char *s, int n)
{
	while (n-- > 0)
		put(o, *s++);
}

/* Space padding before, prefix (sign, 0x), zeros, then the body via a callback-free
 * split: callers emit the body themselves between field_begin and field_end. */
static int field_begin(struct fmt_out *o, const struct fmt_spec *sp, const char *prefix,
		       int plen, int zeros, int body_len, int zero_pad_ok)
{
	int total = plen + zeros + body_len;
	int pad = sp->width > total ? sp->width - total : 0;

	if (!sp->left && !(sp->zero && zero_pad_ok))
		put_rep(o, ' ', pad);
	put_str(o, prefix, plen);
	if (!sp->left && sp->zero && zero_pad_ok)
		put_rep(o, '0', pad);
	put_rep(o, '0', zeros);
	return sp->left ? pad : 0;
}

static void fmt_int(struct fmt_out *o, const struct fmt_spec *sp, rtapi_u64 v, int neg, int base)
{
	char tmp[24], prefix[3];
	const char *digits = sp->conv == 'X' ? "0123456789ABCDEF" : "0123456789abcdef";
	int n = 0, plen = 0, prec = sp->prec, zeros, pad;

	while (v) {
		rtapi_u32 d;

		v = rtapi_div_u64_rem(v, (rtapi_u32)base, &d);
		tmp[sizeof(tmp) - 1 - n++] = digits[d];
	}
	if (prec < 0)
		prec = 1;
	if (sp->alt && base == 8 && prec <= n)	/* # makes octal start with 0 */
		prec = n + 1;
	if (neg)
		prefix[plen++] = '-';
	else if ((sp->conv == 'd' || sp->conv == 'i') && sp->plus)
		prefix[plen++] = '+';
	else if ((sp->conv == 'd' || sp->conv == 'i') && sp->space)
		prefix[plen++] = ' ';
	if ((sp->alt && base == 16 && n) || sp->conv == 'p') {
		prefix[plen++] = '0';
		prefix[plen++] = sp->conv == 'X' ? 'X' : 'x';
	}
	zeros = prec > n ? prec - n : 0;
	pad = field_begin(o, sp, prefix, plen, zeros, n, sp->prec < 0);
	put_str(o, tmp + sizeof(tmp) - n, n);
	put_rep(o, ' ', pad);
}

static void fmt_str(struct fmt_out *o, const struct fmt_spec *sp, const char *s)
{
	int n = 0, pad;

	if (!s)
		s = "(null)";
	while (s[n] && (sp->prec < 0 || n < sp->prec))
		n++;
	pad = field_begin(o, sp, "", 0, 0, n, 0);
	put_str(o, s, n);
	put_rep(o, ' ', pad);
}

/* --- exact decimal expansion of a double --- */

/* Multiply the little-endian number w[0..nw-1] by m, return the carry out. */
static rtapi_u32 big_mul(rtapi_u32 *w, int nw, rtapi_u32 m)
{
	rtapi_u64 carry = 0;
	int i;

	for (i = 0; i < nw; i++) {
		carry += (rtapi_u64)w[i] * m;
		w[i] = (rtapi_u32)carry;
		carry >>= 32;
	}
	return (rtapi_u32)carry;
}

/* Divide w by 10^9 in place, return the remainder. */
static rtapi_u32 big_div1e9(rtapi_u32 *w, int nw)
{
	rtapi_u32 rem = 0;
	int i;

	for (i = nw - 1; i >= 0; i--) {
		rtapi_u64 cur = ((rtapi_u64)rem << 32) | w[i];

		w[i] = (rtapi_u32)rtapi_div_u64_rem(cur, 1000000000u, &rem);
	}
	return rem;
}

static int big_is_zero(const rtapi_u32 *w, int nw)
{
	while (nw-- > 0)
		if (w[nw])
			return 0;
	return 1;
}

/* Integer part digits of m * 2^e (e >= 0) into dec; uses w as scratch. */
static void int_digits(rtapi_u64 m, int e, rtapi_u32 *w, struct fmt_decimal *dec)
{
	int nw = (53 + e) / 32 + 2, i, k, end = FMT_DIGITS;

	for (i = 0; i < nw; i++)
		w[i] = 0;
	for (i = 0; i < 3; i++) {	/* m spans at most three words */
		int shift = i * 32 - e % 32;

		if (shift < 64)
			w[e / 32 + i] = (rtapi_u32)(shift >= 0 ? m >> shift : m << -shift);
	}
	/* chunks of nine digits, least significant first, stored from the end of d[] */
	while (!big_is_zero(w, nw)) {
		rtapi_u32 rem = big_div1e9(w, nw);

		for (k = 0; k < 9; k++) {
			dec->d[--end] = (unsigned char)(rem % 10);
			rem /= 10;
		}
	}
	while (end < FMT_DIGITS && dec->d[end] == 0)
		end++;
	for (i = 0; end + i < FMT_DIGITS; i++)
		dec->d[i] = dec->d[end + i];
	dec->n = i;
	dec->exp10 = i - 1;
}

/* The fraction fr / 2^s (s >= 1) as a fixed-point number of nw 32-bit words whose
 * binary point sits just above the top word; returns nw. */
static int frac_words(rtapi_u64 fr, int s, rtapi_u32 *w)
{
	int sh = (32 - s % 32) % 32;	/* shift so that the point falls on a word boundary */
	int nw = (s + sh) / 32, i;

	for (i = 0; i < nw; i++) {
		int off = i * 32 - sh;	/* bit of fr that lands at bit 0 of word i */

		if (off >= 64)
			w[i] = 0;
		else
			w[i] = (rtapi_u32)(off >= 0 ? fr >> off : fr << -off);
	}
	return nw;
}

/* Round the digits of dec to 'keep' digits, half to even; 'sticky' says whether
 * anything nonzero follows the digits stored. */
static void round_digits(struct fmt_decimal *dec, int keep, int sticky, char mode)
{
	int i, up, rd = keep < dec->n ? dec->d[keep] : 0;

	for (i = keep + 1; i < dec->n; i++)
		sticky |= dec->d[i];
	up = rd > 5 || (rd == 5 && (sticky || (keep > 0 && (dec->d[keep - 1] & 1))));
	if (keep > FMT_DIGITS)
		keep = FMT_DIGITS;	/* precision beyond what we keep: print zeros */
	for (i = dec->n; i < keep; i++)
		dec->d[i] = 0;
	dec->n = keep;
	for (i = keep - 1; up && i >= 0; i--) {
		if (dec->d[i] == 9) {
			dec->d[i] = 0;
		} else {
			dec->d[i]++;
			up = 0;
		}
	}
	if (up) {		/* 9.99 -> 10.0: a new leading digit */
		dec->d[0] = 1;
		for (i = 1; i < dec->n; i++)
			dec->d[i] = 0;
		if (dec->n == 0 || (mode == 'f' && dec->n < FMT_DIGITS))
			dec->d[dec->n++] = 0;
		dec->d[0] = 1;
		dec->exp10++;
	}
}

/* Exact digits of a positive finite double given by its bits, rounded half-to-even
 * at decimal position -prec (mode 'f') or to prec+1 significant digits (mode 'e'). */
static void fmt_decimal_round(rtapi_u64 bits, char mode, int prec, struct fmt_decimal *dec)
{
	rtapi_u32 w[FMT_WORDS];
	rtapi_u64 m = bits & 0x000fffffffffffffULL;
	int e = (int)(bits >> 52) & 0x7ff;
	int nw = 0, keep, rd;

	if (e) {
		m |= 1ULL << 52;
		e -= 1075;
	} else {
		e = -1074;
	}
	dec->n = 0;
	dec->exp10 = -1;
	if (e >= 0) {
		int_digits(m, e, w, dec);	/* no fraction */
	} else {
		rtapi_u64 ip = -e < 64 ? m >> -e : 0;
		rtapi_u64 fr = -e < 64 ? m & ((1ULL << -e) - 1) : m;

		if (ip)
			int_digits(ip, 0, w, dec);
		nw = frac_words(fr, -e, w);
	}
	if (dec->n == 0) {	/* 0 < x < 1: find the first nonzero fraction digit */
		for (;;) {
			rd = (int)big_mul(w, nw, 10);
			if (rd)
				break;
			dec->exp10--;
			if (mode == 'f' && dec->exp10 < -prec - 1)
				return;		/* rounds to zero */
		}
		dec->d[dec->n++] = (unsigned char)rd;
	}
	keep = dec->exp10 + 1 + (mode == 'f' ? prec : prec - dec->exp10);
	while (dec->n <= keep && dec->n < FMT_DIGITS && !big_is_zero(w, nw))
		dec->d[dec->n++] = (unsigned char)big_mul(w, nw, 10);
	round_digits(dec, keep, !big_is_zero(w, nw), mode);
}

/* Digit of dec at decimal position p (10^p), '0' outside the stored digits. */
static char digit_at(const struct fmt_decimal *dec, int p)
{
	int i = dec->exp10 - p;

	return (i >= 0 && i < dec->n) ? (char)('0' + dec->d[i]) : '0';
}

static int exp_len(int x)
{
	if (x < 0)
		x = -x;
	return x >= 100 ? (x >= 1000 ? 4 : 3) : 2;
}

/* Emit 'f' or 'e' style from dec; trim removes trailing fraction zeros (%g). */
static void emit_float(struct fmt_out *o, const struct fmt_spec *sp, const char *prefix,
		       int plen, const struct fmt_decimal *dec, char style, int prec, int trim)
{
	int x = dec->n ? dec->exp10 : 0;	/* decimal exponent of the first digit */
	int top = style == 'f' ? (x > 0 ? x : 0) : x;	/* position of the first digit printed */
	int ip = style == 'f' ? top + 1 : 1;		/* digits before the point */
	int len, pad, k, dot, elen = exp_len(x);
	char ebuf[4];

	while (trim && prec > 0 && digit_at(dec, top - ip + 1 - prec) == '0')
		prec--;
	dot = prec > 0 || sp->alt;
	len = ip + dot + prec + (style == 'e' ? 2 + elen : 0);
	pad = field_begin(o, sp, prefix, plen, 0, len, 1);
	for (k = 0; k < ip + prec; k++) {
		if (k == ip && dot)
			put(o, '.');
		put(o, digit_at(dec, top - k));
	}
	if (dot && prec == 0)
		put(o, '.');
	if (style == 'e') {
		put(o, sp->conv < 'a' ? 'E' : 'e');
		put(o, x < 0 ? '-' : '+');
		x = x < 0 ? -x : x;
		for (k = elen - 1; k >= 0; k--) {
			ebuf[k] = (char)('0' + x % 10);
			x /= 10;
		}
		put_str(o, ebuf, elen);
	}
	put_rep(o, ' ', pad);
}

/* Print the double whose IEEE bits these are, per sp (conv f F e E g G). */
static void fmt_float_bits(struct fmt_out *o, const struct fmt_spec *sp, rtapi_u64 bits)
{
	int neg = (int)(bits >> 63), plen = 0, upper = sp->conv < 'a';
	int prec = sp->prec < 0 ? 6 : sp->prec, pad;
	char prefix[2], conv = (char)(sp->conv | 0x20);
	struct fmt_decimal dec;

	if (neg)
		prefix[plen++] = '-';
	else if (sp->plus)
		prefix[plen++] = '+';
	else if (sp->space)
		prefix[plen++] = ' ';
	bits &= ~(1ULL << 63);
	if ((bits >> 52) == 0x7ff) {	/* inf, nan: never zero padded */
		const char *t = (bits << 12) ? (upper ? "NAN" : "nan") : (upper ? "INF" : "inf");

		pad = field_begin(o, sp, prefix, plen, 0, 3, 0);
		put_str(o, t, 3);
		put_rep(o, ' ', pad);
		return;
	}
	dec.n = 0;
	dec.exp10 = 0;
	if (conv == 'f') {
		if (bits)
			fmt_decimal_round(bits, 'f', prec, &dec);
		emit_float(o, sp, prefix, plen, &dec, 'f', prec, 0);
	} else if (conv == 'e') {
		if (bits)
			fmt_decimal_round(bits, 'e', prec, &dec);
		emit_float(o, sp, prefix, plen, &dec, 'e', prec, 0);
	} else {			/* g: P significant digits, style by exponent */
		int P = prec ? prec : 1, X = 0;

		if (bits) {
			fmt_decimal_round(bits, 'e', P - 1, &dec);
			X = dec.exp10;
		}
		if (P > X && X >= -4) {
			if (bits)
				fmt_decimal_round(bits, 'f', P - 1 - X, &dec);
			emit_float(o, sp, prefix, plen, &dec, 'f', P - 1 - X, !sp->alt);
		} else {
			emit_float(o, sp, prefix, plen, &dec, 'e', P - 1, !sp->alt);
		}
	}
}

/* The one place that touches a double: take it from the argument list as bits. */
static void fmt_double(struct fmt_out *o, const struct fmt_spec *sp, va_list *ap)
{
	union { double d; rtapi_u64 u; } b;

	b.d = va_arg(*ap, double);
	fmt_float_bits(o, sp, b.u);
}

/* Read the flags, width, precision and length of one conversion after '%'. */
static const char *parse_spec(const char *f, struct fmt_spec *sp, int *len, va_list *ap)
{
	sp->left = sp->plus = sp->space = sp->alt = sp->zero = 0;
	sp->width = 0;
	sp->prec = -1;
	for (;; f++) {
		if (*f == '-')
			sp->left = 1;
		else if (*f == '+')
			sp->plus = 1;
		else if (*f == ' ')
			sp->space = 1;
		else if (*f == '#')
			sp->alt = 1;
		else if (*f == '0')
			sp->zero = 1;
		else
			break;
	}
	if (*f == '*') {
		sp->width = va_arg(*ap, int);
		if (sp->width < 0) {
			sp->left = 1;
			sp->width = -sp->width;
		}
		f++;
	}
	while (*f >= '0' && *f <= '9')
		sp->width = sp->width * 10 + (*f++ - '0');
	if (*f == '.') {
		f++;
		sp->prec = 0;
		if (*f == '*') {
			sp->prec = va_arg(*ap, int);
			if (sp->prec < 0)
				sp->prec = -1;
			f++;
		}
		while (*f >= '0' && *f <= '9')
			sp->prec = sp->prec * 10 + (*f++ - '0');
	}
	/* length: 1 char, 2 short, 4 int, 8 long, 16 long long / size_t / intmax_t */
	*len = 4;
	if (f[0] == 'h' && f[1] == 'h') {
		*len = 1;
		f += 2;
	} else if (f[0] == 'l' && f[1] == 'l') {
		*len = 16;
		f += 2;
	} else if (*f == 'h') {
		*len = 2;
		f++;
	} else if (*f == 'l') {
		*len = 8;
		f++;
	} else if (*f == 'z' || *f == 'j' || *f == 't') {
		*len = 16;
		f++;
	}
	sp->conv = *f;
	return f;
}

static void fmt_signed(struct fmt_out *o, const struct fmt_spec *sp, int len, va_list *ap)
{
	long long v;

	if (len == 16)
		v = va_arg(*ap, long long);
	else if (len == 8)
		v = va_arg(*ap, long);
	else
		v = va_arg(*ap, int);
	if (len == 1)
		v = (signed char)v;
	else if (len == 2)
		v = (short)v;
	fmt_int(o, sp, v < 0 ? -(rtapi_u64)v : (rtapi_u64)v, v < 0, 10);
}

static void fmt_unsigned(struct fmt_out *o, const struct fmt_spec *sp, int len, va_list *ap)
{
	rtapi_u64 v;
	int base = sp->conv == 'o' ? 8 : sp->conv == 'u' ? 10 : 16;

	if (len == 16)
		v = va_arg(*ap, unsigned long long);
	else if (len == 8)
		v = va_arg(*ap, unsigned long);
	else
		v = va_arg(*ap, unsigned int);
	if (len == 1)
		v = (unsigned char)v;
	else if (len == 2)
		v = (unsigned short)v;
	fmt_int(o, sp, v, 0, base);
}

int rtapi_vsnprintf(char *buf, unsigned long int size, const char *fmt, va_list ap)
{
	struct fmt_out o = { buf, size, 0 };
	struct fmt_spec sp;
	va_list args;
	const char *start;
	int len;

	va_copy(args, ap);
	for (; *fmt; fmt++) {
		if (*fmt != '%') {
			put(&o, *fmt);
			continue;
		}
		start = fmt;
		fmt = parse_spec(fmt + 1, &sp, &len, &args);
		switch (sp.conv) {
		case 'd':
		case 'i':
			fmt_signed(&o, &sp, len, &args);
			break;
		case 'u':
		case 'x':
		case 'X':
		case 'o':
			fmt_unsigned(&o, &sp, len, &args);
			break;
		case 'p': {
			void *p = va_arg(args, void *);

			if (p) {
				fmt_int(&o, &sp, (rtapi_u64)(unsigned long)p, 0, 16);
			} else {
				sp.prec = -1;
				fmt_str(&o, &sp, "(nil)");
			}
			break;
		}
		case 'c': {
			char c = (char)va_arg(args, int);
			int pad = field_begin(&o, &sp, "", 0, 0, 1, 0);

			put(&o, c);
			put_rep(&o, ' ', pad);
			break;
		}
		case 's':
			fmt_str(&o, &sp, va_arg(args, const char *));
			break;
		case 'f':
		case 'F':
		case 'e':
		case 'E':
		case 'g':
		case 'G':
			fmt_double(&o, &sp, &args);
			break;
		case '%':
			put(&o, '%');
			break;
		default:	/* unknown conversion: copy it as written */
			while (start <= fmt && *start)
				put(&o, *start++);
			if (!*fmt)
				fmt--;
			break;
		}
	}
	va_end(args);
	if (size)
		buf[o.len < size ? o.len : size - 1] = '\0';
	return (int)o.len;
}

int rtapi_snprintf(char *buf, unsigned long int size, const char *fmt, ...)
{
	va_list ap;
	int n;

	va_start(ap, fmt);
	n = rtapi_vsnprintf(buf, size, fmt, ap);
	va_end(ap);
	return n;
}
