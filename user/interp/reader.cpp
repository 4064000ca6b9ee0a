// SPDX-License-Identifier: GPL-2.0-or-later
// reader.cpp - one line of G-code into a Block (gcode.md section 1): comments, block
// delete, line numbers, words, parameter settings, O-word headers. Values are
// evaluated here, with the parameters as they were before the line (expr.cpp).
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "impl.hpp"

namespace rs274 {

std::string fmt(const char* f, ...)
{
	char buf[512];
	va_list ap;
	va_start(ap, f);
	vsnprintf(buf, sizeof buf, f, ap);
	va_end(ap);
	return buf;
}

void fail(const char* f, ...)
{
	char buf[512];
	va_list ap;
	va_start(ap, f);
	vsnprintf(buf, sizeof buf, f, ap);
	va_end(ap);
	throw InterpError{buf};
}

bool Block::has_g(int code) const
{
	for (int c : g)
		if (c == code)
			return true;
	return false;
}

bool Block::has_m(int code) const
{
	for (int c : m)
		if (c == code)
			return true;
	return false;
}

bool Block::any_axis() const
{
	for (char c : {'x', 'y', 'z', 'a', 'b', 'c', 'u', 'v', 'w', '@', '^'})
		if (w(c))
			return true;
	return false;
}

int g_group(int c)
{
	switch (c) {
	case 40: case 53: case 100: case 280: case 281: case 300: case 301: case 520: case 530: case 920:
		return 0;
	case 0: case 10: case 20: case 30: case 50: case 51: case 52: case 330: case 331: case 382: case 383: case 384: case 385:
	case 730: case 740: case 760: case 800: case 810: case 820: case 830: case 840: case 850:
	case 860: case 870: case 880: case 890:
		return 1;
	case 170: case 180: case 190: case 171: case 181: case 191: return 2;
	case 900: case 910: return 3;
	case 901: case 911: return 4;
	case 930: case 940: case 950: return 5;
	case 200: case 210: return 6;
	case 400: case 410: case 420: case 411: case 421: return 7;
	case 430: case 431: case 432: case 490: return 8;
	case 980: case 990: return 10;
	case 540: case 550: case 560: case 570: case 580: case 590: case 591: case 592: case 593:
		return 12;
	case 610: case 611: case 640: return 13;
	case 960: case 970: return 14;
	case 70: case 80: return 15;
	case 921: case 922: case 923: return 16;
	default: return -1;
	}
}

int m_group(int c)
{
	switch (c) {
	case 0: case 1: case 2: case 30: case 60: case 98: case 99: return 4;
	case 62: case 63: case 64: case 65: case 66: case 67: case 68: return 5;
	case 6: case 61: return 6;
	case 3: case 4: case 5: case 19: case 70: case 71: case 72: case 73: return 7;
	case 7: case 8: case 9: return 8;
	case 48: case 49: case 50: case 51: case 52: case 53: return 9;
	default: return c >= 100 && c <= 199 ? 10 : -1;
	}
}

std::string normalize_line(const std::string& raw, std::string* comment, bool* has_comment)
{
	std::string t;
	t.reserve(raw.size());
	for (size_t i = 0; i < raw.size(); i++) {
		char c = raw[i];
		if (c == '(') {
			size_t j = i + 1;
			for (; j < raw.size() && raw[j] != ')'; j++)
				if (raw[j] == '(')
					fail("Nested comment found");
			if (j >= raw.size())
				fail("Unclosed comment found");
			if (comment) {
				*comment = raw.substr(i + 1, j - i - 1);
				*has_comment = true;
			}
			t += '\x01';
			i = j;
		} else if (c == ';') {
			if (comment) {
				*comment = raw.substr(i + 1);
				*has_comment = true;
			}
			break;
		} else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
			continue;
		} else {
			t += (char)std::tolower((unsigned char)c);
		}
	}
	return t;
}

static const struct { const char* word; OKind kind; } o_keywords[] = {
	{"endsub", O_ENDSUB}, {"endif", O_ENDIF}, {"endwhile", O_ENDWHILE},
	{"endrepeat", O_ENDREPEAT}, {"elseif", O_ELSEIF}, {"else", O_ELSE}, {"sub", O_SUB},
	{"call", O_CALL}, {"return", O_RETURN}, {"if", O_IF}, {"while", O_WHILE}, {"do", O_DO},
	{"break", O_BREAK}, {"continue", O_CONTINUE}, {"repeat", O_REPEAT},
};

// Skips "/" and "nNNN[.NNN]" at the start of a normalized line.
static size_t skip_line_start(const std::string& t, size_t i)
{
	while (i < t.size() && t[i] == '\x01')
		i++;
	if (i < t.size() && t[i] == 'n') {
		i++;
		while (i < t.size() && (std::isdigit((unsigned char)t[i]) || t[i] == '.'))
			i++;
	}
	return i;
}

static OKind read_o_keyword(const std::string& t, size_t& i)
{
	size_t j = i;
	while (j < t.size() && t[j] == '\x01')
		j++;
	if (j >= t.size())
		return O_FANUC;   // nothing (or only a comment) after the label
	for (const auto& k : o_keywords) {
		size_t n = std::strlen(k.word);
		if (t.compare(i, n, k.word) == 0) {
			i += n;
			return k.kind;
		}
	}
	fail("Unknown word where unary operation could be");
}

// A static label: digits ("o0100" -> "100") or <name>.
static bool read_static_label(const std::string& t, size_t& i, std::string& label)
{
	if (i < t.size() && t[i] == '<') {
		size_t j = t.find('>', i);
		if (j == std::string::npos)
			fail("Named parameter not terminated");
		label = t.substr(i, j - i + 1);
		i = j + 1;
		return true;
	}
	if (i < t.size() && std::isdigit((unsigned char)t[i])) {
		long v = 0;
		while (i < t.size() && std::isdigit((unsigned char)t[i])) {
			if (v < 100000000)
				v = v * 10 + (t[i] - '0');
			i++;
		}
		label = std::to_string(v);
		return true;
	}
	return false;
}

bool has_m99(const std::string& raw)
{
	try {
		std::string t = normalize_line(raw, nullptr, nullptr);
		for (size_t p = t.find("m99"); p != std::string::npos; p = t.find("m99", p + 1)) {
			char n = p + 3 < t.size() ? t[p + 3] : '\0';
			if (!std::isdigit((unsigned char)n) && n != '.')
				return true;
		}
	} catch (const InterpError&) {
	}
	return false;
}

bool o_header(const std::string& raw, std::string& label, OKind& kind)
{
	try {
		std::string t = normalize_line(raw, nullptr, nullptr);
		size_t i = 0;
		if (i < t.size() && t[i] == '/')
			i++;
		i = skip_line_start(t, i);
		if (i >= t.size() || t[i] != 'o')
			return false;
		i++;
		if (!read_static_label(t, i, label))
			return false;
		kind = read_o_keyword(t, i);
		return true;
	} catch (const InterpError&) {
		return false;
	}
}

void Interp::Impl::read_o_word(const std::string& t, size_t& i, Block& b)
{
	i++;   // 'o'
	if (!read_static_label(t, i, b.o_label)) {
		if (i < t.size() && t[i] == '[') {
			double v = read_real(t, i);
			b.o_label = std::to_string(std::lround(v));
		} else {
			fail("Bad format of o-word label");
		}
	}
	b.o = read_o_keyword(t, i);
	if (b.o == O_FANUC && !std::isdigit((unsigned char)b.o_label[0]))
		fail("Fanuc-style program number o%s must be a number", b.o_label.c_str());
	b.o_rest = t.substr(i);
	// Nothing but a comment after the statement's own expressions is checked when
	// they are evaluated (oword.cpp).
}

Block Interp::Impl::read_block(const std::string& raw0, int line)
{
	Block b;
	b.line = line;
	std::string raw = raw0;
	while (!raw.empty() && (raw.back() == '\n' || raw.back() == '\r'))
		raw.pop_back();
	if (raw.size() >= MAX_LINE)
		fail("Command too long");
	std::string t = normalize_line(raw, &b.comment, &b.has_comment);
	size_t i = 0;
	while (i < t.size() && t[i] == '\x01')
		i++;
	if (i < t.size() && t[i] == '/') {
		if (block_delete)
			return b;
		i++;
	}
	i = skip_line_start(t, i);
	b.empty = !b.has_comment;
	if (i < t.size() && t[i] == 'o') {
		read_o_word(t, i, b);
		b.empty = false;
		return b;
	}
	read_items(t, i, b);
	if (b.empty)
		return b;
	check_block(b);
	return b;
}

static bool axis_letter(char c, int& axis)
{
	static const char letters[] = "xyzabcuvw";
	const char* p = std::strchr(letters, c);
	if (!p || !c)
		return false;
	axis = (int)(p - letters);
	return true;
}

static int to_int(double v)
{
	double r = std::nearbyint(v);
	if (std::fabs(v - r) > 0.0001)
		fail("Non integer value for integer");
	if (!(std::fabs(r) <= 2e9))   // also NaN
		fail("Non integer value for integer");
	return (int)r;
}

void Interp::Impl::read_items(const std::string& t, size_t& i, Block& b)
{
	while (i < t.size()) {
		char c = t[i];
		if (c == '\x01') {
			i++;
			continue;
		}
		b.empty = false;
		if (c == '#') {
			i++;
			bool named = i < t.size() && t[i] == '<';
			std::string name;
			int idx = 0;
			if (named)
				name = read_param_name(t, i);
			else
				idx = to_int(read_real(t, i));
			if (i >= t.size() || t[i] != '=')
				fail("Equal sign missing in parameter setting");
			i++;
			double v = read_real(t, i);
			if (named) {
				b.name_sets.emplace_back(name, v);
			} else {
				if (idx < 1 || idx >= MAX_PARAM)
					fail("Parameter number out of range");
				b.num_sets.emplace_back(idx, v);
			}
			continue;
		}
		if (c == 'o')
			fail("Unknown word starting with o");
		if (c == 'n')
			fail("Line number must come first (n word not at start of line)");
		int axis;
		bool known = (c >= 'a' && c <= 'z') || c == '$' || c == '@' || c == '^';
		if (axis_letter(c, axis) && !axis_on[axis])
			known = false;
		if (!known) {
			if (std::isprint((unsigned char)c))
				fail("Unknown word starting with %c", c);
			fail("Bad character used");
		}
		i++;
		double v = read_real(t, i);
		if (c == 'g') {
			double r = std::nearbyint(v * 10);
			if (!(std::fabs(v * 10 - r) <= 0.001))   // also NaN
				fail("Non integer value for integer");
			if (r < 0)
				fail("Negative g code used");
			if (r > 999)
				fail("G-code out of range");
			int code = (int)r;
			int grp = g_group(code);
			if (grp < 0)
				fail("Unknown g code used");
			if (b.gmode[grp] != -1)
				fail("Two g codes used from same modal group");
			b.gmode[grp] = code;
			b.g.push_back(code);
			continue;
		}
		if (c == 'm') {
			int code = to_int(v);
			if (code < 0)
				fail("Negative m code used");
			if (code > 199)
				fail("M-code greater than 199: M%d", code);
			int grp = m_group(code);
			if (grp < 0 || ((code == 98 || code == 99) && cfg.disable_fanuc_style_sub))
				fail("Unknown m code used: M%d", code);
			if (b.m.size() >= 4)
				fail("Too many m codes on line");
			// M7 and M8 may share a line (mist and flood both on).
			bool coolant_pair = grp == 8 && code != 9 && b.mmode[8] != -1 && b.mmode[8] != 9 &&
			                    b.mmode[8] != code;
			if (b.mmode[grp] != -1 && !coolant_pair)
				fail("Two m codes used from same modal group");
			b.mmode[grp] = code;
			b.m.push_back(code);
			continue;
		}
		if (b.has[(unsigned char)c])
			fail("Multiple %c words on one line", c);
		switch (c) {
		case 'f': if (v < 0) fail("Negative f word used"); break;
		case 's': if (v < 0) fail("Negative spindle speed used"); break;
		case 't':
			if (v < 0)
				fail("Negative tool id (tool not found)");
			v = to_int(v);
			break;
		case 'l':
			if (v < 0)
				fail("Negative l word used");
			v = to_int(v);
			break;
		case 'h':
			if (v < 0)
				fail("Negative h word used");
			break;
		case 'd':
			if (v < 0)
				fail("Negative d word used");
			break;
		case '$':
			v = to_int(v);
			if (v < -1 || v > 0)
				fail("Spindle number out of range (only spindle 0 is configured)");
			break;
		default: break;
		}
		b.has[(unsigned char)c] = true;
		b.val[(unsigned char)c] = v;
	}
}

}  // namespace rs274
