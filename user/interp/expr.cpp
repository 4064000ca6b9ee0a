// SPDX-License-Identifier: GPL-2.0-or-later
// expr.cpp - real values (gcode.md section 5): numbers, #parameters, [expressions]
// with binary operators by precedence, and the unary functions. Recursion is bounded
// by MAX_EXPR_DEPTH (and the 255-character line) so hostile input cannot exhaust the stack.
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "impl.hpp"

namespace rs274 {

namespace {

enum Op { OP_NONE, OP_POW, OP_MUL, OP_DIV, OP_MOD, OP_ADD, OP_SUB, OP_EQ, OP_NE, OP_GT, OP_GE,
          OP_LT, OP_LE, OP_AND, OP_OR, OP_XOR, OP_END };

int precedence(Op op)
{
	switch (op) {
	case OP_POW: return 5;
	case OP_MUL: case OP_DIV: case OP_MOD: return 4;
	case OP_ADD: case OP_SUB: return 3;
	case OP_EQ: case OP_NE: case OP_GT: case OP_GE: case OP_LT: case OP_LE: return 2;
	case OP_AND: case OP_OR: case OP_XOR: return 1;
	default: return 0;
	}
}

// Reads the operator at t[i] (or "]"), advancing i.
Op read_op(const std::string& t, size_t& i)
{
	if (i >= t.size())
		fail("Unclosed expression");
	static const struct { const char* s; Op op; } names[] = {
		{"**", OP_POW}, {"*", OP_MUL}, {"/", OP_DIV}, {"+", OP_ADD}, {"-", OP_SUB},
		{"]", OP_END}, {"mod", OP_MOD}, {"eq", OP_EQ}, {"ne", OP_NE}, {"gt", OP_GT},
		{"ge", OP_GE}, {"lt", OP_LT}, {"le", OP_LE}, {"and", OP_AND}, {"or", OP_OR},
		{"xor", OP_XOR},
	};
	for (const auto& n : names) {
		size_t len = std::strlen(n.s);
		if (t.compare(i, len, n.s) == 0) {
			i += len;
			return n.op;
		}
	}
	fail("Unknown operation");
}

constexpr double EQ_TOL = 1e-6;

double apply(Op op, double a, double b)
{
	switch (op) {
	case OP_POW:
		if (a < 0 && std::floor(b) != b)
			fail("Attempt to raise negative to non integer power");
		return std::pow(a, b);
	case OP_MUL: return a * b;
	case OP_DIV:
		if (b == 0)
			fail("Attempt to divide by zero");
		return a / b;
	case OP_MOD: {
		if (b == 0)
			fail("Attempt to divide by zero");
		double r = std::fmod(a, b);
		if (r < 0)
			r += std::fabs(b);
		return r;
	}
	case OP_ADD: return a + b;
	case OP_SUB: return a - b;
	case OP_EQ: return std::fabs(a - b) < EQ_TOL ? 1 : 0;
	case OP_NE: return std::fabs(a - b) < EQ_TOL ? 0 : 1;
	case OP_GT: return a > b ? 1 : 0;
	case OP_GE: return (a > b || std::fabs(a - b) < EQ_TOL) ? 1 : 0;
	case OP_LT: return a < b ? 1 : 0;
	case OP_LE: return (a < b || std::fabs(a - b) < EQ_TOL) ? 1 : 0;
	case OP_AND: return (a != 0 && b != 0) ? 1 : 0;
	case OP_OR: return (a != 0 || b != 0) ? 1 : 0;
	case OP_XOR: return ((a != 0) != (b != 0)) ? 1 : 0;
	default: fail("Unknown operation");
	}
}

constexpr double DEG = M_PI / 180.0;

}  // namespace

double Interp::Impl::read_real(const std::string& t, size_t& i, int depth)
{
	if (depth > MAX_EXPR_DEPTH)
		fail("Expression nested too deeply (more than %d levels)", MAX_EXPR_DEPTH);
	if (i >= t.size())
		fail("Missing value at end of line");
	char c = t[i];
	if (c == '[')
		return read_expression(t, i, depth + 1);
	if (c == '#')
		return read_param_ref(t, i, depth + 1);
	if (c == '+' || c == '-') {
		i++;   // the sign binds to the value it precedes: -7 MOD 3 is (-7) MOD 3
		double v = read_real(t, i, depth + 1);
		return c == '-' ? -v : v;
	}
	if (std::isalpha((unsigned char)c))
		return read_unary(t, i, depth + 1);
	if (std::isdigit((unsigned char)c) || c == '.') {
		size_t j = i;
		int digits = 0, dots = 0;
		for (; j < t.size(); j++) {
			if (std::isdigit((unsigned char)t[j]))
				digits++;
			else if (t[j] == '.' && dots == 0)
				dots++;
			else
				break;
		}
		if (digits == 0)
			fail("Bad number format");
		double v = std::strtod(t.substr(i, j - i).c_str(), nullptr);
		i = j;
		return v;
	}
	fail("Bad number format");
}

double Interp::Impl::read_expression(const std::string& t, size_t& i, int depth)
{
	if (depth > MAX_EXPR_DEPTH)
		fail("Expression nested too deeply (more than %d levels)", MAX_EXPR_DEPTH);
	i++;   // '['
	// Operator-precedence reduction with explicit stacks (at most 5 levels deep).
	double vals[8];
	Op ops[8];
	int n = 0;
	vals[0] = read_real(t, i, depth);
	while (true) {
		Op op = read_op(t, i);
		while (n > 0 && (op == OP_END || precedence(ops[n - 1]) >= precedence(op))) {
			vals[n - 1] = apply(ops[n - 1], vals[n - 1], vals[n]);
			n--;
		}
		if (op == OP_END)
			return vals[0];
		ops[n] = op;
		n++;
		vals[n] = read_real(t, i, depth);
	}
}

double Interp::Impl::read_unary(const std::string& t, size_t& i, int depth)
{
	size_t j = i;
	while (j < t.size() && std::isalpha((unsigned char)t[j]))
		j++;
	std::string name = t.substr(i, j - i);
	static const char* const names[] = {"abs", "acos", "asin", "atan", "cos", "exp", "fix",
	                                    "fup", "round", "ln", "sin", "sqrt", "tan", "exists"};
	bool known = false;
	for (const char* n : names)
		if (name == n)
			known = true;
	if (!known)
		fail("Unknown word where unary operation could be");
	i = j;
	if (i >= t.size() || t[i] != '[')
		fail("Left bracket missing after unary operation name");
	if (name == "exists") {
		i++;
		if (i >= t.size() || t[i] != '#' || i + 1 >= t.size() || t[i + 1] != '<')
			fail("EXISTS argument must be a named parameter #<name>");
		i++;
		std::string pname = read_param_name(t, i);
		if (i >= t.size() || t[i] != ']')
			fail("Unclosed expression");
		i++;
		double v;
		return get_named(pname, v) ? 1 : 0;
	}
	double a = read_expression(t, i, depth);
	if (name == "atan") {
		if (i >= t.size() || t[i] != '/')
			fail("Slash missing after first atan argument");
		i++;
		if (i >= t.size() || t[i] != '[')
			fail("Left bracket missing after slash with atan");
		double x = read_expression(t, i, depth);
		return std::atan2(a, x) / DEG;
	}
	if (name == "abs") return std::fabs(a);
	if (name == "acos" || name == "asin") {
		if (a < -1 || a > 1)
			fail(name == "acos" ? "Argument to acos out of range" : "Argument to asin out of range");
		return (name == "acos" ? std::acos(a) : std::asin(a)) / DEG;
	}
	if (name == "cos") return std::cos(a * DEG);
	if (name == "sin") return std::sin(a * DEG);
	if (name == "tan") return std::tan(a * DEG);
	if (name == "exp") return std::exp(a);
	if (name == "fix") return std::floor(a);
	if (name == "fup") return std::ceil(a);
	if (name == "round") return std::round(a);
	if (name == "ln") {
		if (a <= 0)
			fail("Zero or negative argument to ln");
		return std::log(a);
	}
	// sqrt
	if (a < 0)
		fail("Negative argument to sqrt");
	return std::sqrt(a);
}

std::string Interp::Impl::read_param_name(const std::string& t, size_t& i)
{
	i++;   // '<'
	size_t j = t.find('>', i);
	if (j == std::string::npos)
		fail("Named parameter not terminated");
	std::string name = t.substr(i, j - i);
	if (name.empty())
		fail("Named parameter name is empty");
	if (name.find('\x01') != std::string::npos)
		fail("Comment inside a named parameter");
	i = j + 1;
	return name;
}

int Interp::Impl::read_int(const std::string& t, size_t& i)
{
	double v = read_real(t, i);
	double r = std::nearbyint(v);
	if (!(std::fabs(v - r) <= 0.0001 && std::fabs(r) <= 2e9))
		fail("Non integer value for integer");
	return (int)r;
}

double Interp::Impl::read_param_ref(const std::string& t, size_t& i, int depth)
{
	i++;   // '#'
	if (i < t.size() && t[i] == '<') {
		std::string name = read_param_name(t, i);
		double v;
		if (!get_named(name, v))
			fail("Named parameter #<%s> not defined", name.c_str());
		return v;
	}
	double v = read_real(t, i, depth);
	double r = std::nearbyint(v);
	if (!(std::fabs(v - r) <= 0.0001))
		fail("Non integer value for integer");
	if (!(r >= 1 && r < MAX_PARAM))
		fail("Parameter number out of range");
	return get_param((int)r);
}

}  // namespace rs274
