// SPDX-License-Identifier: GPL-2.0-or-later
// oword.cpp - O-word flow control and subroutines (gcode.md 6): sub/endsub/call/return,
// if/elseif/else/endif, while/endwhile, do/while, repeat/endrepeat, break/continue,
// and subroutine files found on the search path. Forward jumps scan the source for the
// matching label (results cached); loops remember their start line.
#include <algorithm>
#include <cmath>
#include <fstream>

#include "impl.hpp"

namespace rs274 {

static const char* kind_name(OKind k)
{
	switch (k) {
	case O_SUB: return "sub";
	case O_ENDSUB: return "endsub";
	case O_CALL: return "call";
	case O_RETURN: return "return";
	case O_IF: return "if";
	case O_ELSEIF: return "elseif";
	case O_ELSE: return "else";
	case O_ENDIF: return "endif";
	case O_WHILE: return "while";
	case O_ENDWHILE: return "endwhile";
	case O_DO: return "do";
	case O_BREAK: return "break";
	case O_CONTINUE: return "continue";
	case O_REPEAT: return "repeat";
	case O_ENDREPEAT: return "endrepeat";
	case O_FANUC: return "(program number)";
	default: return "?";
	}
}

static std::string show(const std::string& label) { return "o" + label; }

size_t Interp::Impl::scan(const std::string& label, std::initializer_list<OKind> kinds, size_t from,
                          bool stop_at_sub)
{
	Source& s = *sources[src];
	std::string key = std::to_string(from) + "|" + label;
	for (OKind k : kinds)
		key += "|" + std::to_string((int)k);
	auto c = s.scan_cache.find(key);
	if (c != s.scan_cache.end())
		return c->second;
	for (size_t i = from; i < s.lines.size(); i++) {
		std::string lab;
		OKind k;
		if (!o_header(s.lines[i], lab, k))
			continue;
		if (lab == label && std::find(kinds.begin(), kinds.end(), k) != kinds.end()) {
			if (s.scan_cache.size() < 100000)
				s.scan_cache[key] = i;
			return i;
		}
		if (stop_at_sub && k == O_SUB) {
			cur_line = (int)i + 1;
			fail("Nested subroutine definition (%s sub inside %s)", show(lab).c_str(), show(label).c_str());
		}
	}
	fail("No matching %s %s found", show(label).c_str(), kind_name(*kinds.begin()));
}

double Interp::Impl::eval_rest(const std::string& rest, bool required, bool& present)
{
	size_t i = 0;
	while (i < rest.size() && rest[i] == '\x01')
		i++;
	present = false;
	double v = 0;
	if (i < rest.size() && rest[i] == '[') {
		v = read_expression(rest, i, 1);
		present = true;
	}
	while (i < rest.size() && rest[i] == '\x01')
		i++;
	if (i < rest.size())
		fail("Unexpected text after o-word statement: %s", rest.substr(i).c_str());
	if (required && !present)
		fail("Missing [expression] after o-word statement");
	return v;
}

static LoopBlock* find_loop(Frame& f, const std::string& label)
{
	for (auto it = f.loops.rbegin(); it != f.loops.rend(); ++it)
		if (it->label == label)
			return &*it;
	return nullptr;
}

static void pop_to(Frame& f, const LoopBlock* lb)
{
	while (!f.loops.empty() && &f.loops.back() != lb)
		f.loops.pop_back();
	if (!f.loops.empty())
		f.loops.pop_back();
}

void Interp::Impl::execute_o(Block& b)
{
	if (cfg.max_blocks > 0 && ++blocks > cfg.max_blocks)
		fail("Program exceeded %ld blocks", cfg.max_blocks);
	const std::string& L = b.o_label;
	Frame& f = frames.back();
	bool present;
	auto count = [&](LoopBlock* lb) {
		if (++lb->iterations > cfg.max_loop_iterations)
			fail("Loop %s exceeded %ld iterations", show(L).c_str(), cfg.max_loop_iterations);
	};
	if (nurbs_open)
		fail("Only X Y P control point lines and G5.3 may follow G5.2");
	if (b.o != O_FANUC && src == main_src)
		main_started = true;
	switch (b.o) {
	case O_FANUC:
		if (cfg.disable_fanuc_style_sub)
			fail("%s without a statement (Fanuc-style programs are disabled)", show(L).c_str());
		sub_style_is(2);
		// The main program's own number, or a subprogram reached in sequence: skipped
		// up to its M99 (it runs only when M98 calls it).
		if (src == main_src && frames.size() == 1 && !main_started)
			break;
		pc = fanuc_find_m99(pc, L) + 1;
		break;
	case O_SUB: {
		sub_style_is(1);
		if (frames.size() > 1)
			fail("Nested subroutine definition (%s sub inside a subroutine)", show(L).c_str());
		eval_rest(b.o_rest, false, present);
		subs[L] = SubDef{src, pc - 1};
		pc = scan(L, {O_ENDSUB}, pc, true) + 1;
		break;
	}
	case O_ENDSUB:
	case O_RETURN: {
		if (frames.size() <= 1)
			fail("%s %s outside a subroutine", show(L).c_str(), kind_name(b.o));
		if (f.label != L)
			fail("%s %s does not match the subroutine being run (%s)", show(L).c_str(),
			     kind_name(b.o), show(f.label).c_str());
		double v = eval_rest(b.o_rest, false, present);
		return_sub(present, v);
		break;
	}
	case O_CALL: {
		sub_style_is(1);
		std::vector<double> args;
		const std::string& r = b.o_rest;
		size_t i = 0;
		while (true) {
			while (i < r.size() && r[i] == '\x01')
				i++;
			if (i >= r.size())
				break;
			if (r[i] != '[')
				fail("Subroutine arguments must be [expressions]");
			if (args.size() >= MAX_SUB_ARGS)
				fail("Too many subroutine parameters");
			args.push_back(read_expression(r, i, 1));
		}
		call_sub(L, args);
		break;
	}
	case O_IF: {
		double c = eval_rest(b.o_rest, true, present);
		size_t from = pc;
		while (c == 0) {
			size_t j = scan(L, {O_ELSEIF, O_ELSE, O_ENDIF}, from, false);
			std::string lab;
			OKind k = O_NONE;
			o_header(sources[src]->lines[j], lab, k);
			pc = j + 1;
			if (k != O_ELSEIF)
				break;
			cur_line = (int)j + 1;
			Block eb = read_block(sources[src]->lines[j], (int)j + 1);
			c = eval_rest(eb.o_rest, true, present);
			from = j + 1;
		}
		break;
	}
	case O_ELSEIF:
	case O_ELSE:
		// reached by running off the end of the branch taken: skip to endif
		pc = scan(L, {O_ENDIF}, pc, false) + 1;
		break;
	case O_ENDIF:
		break;
	case O_WHILE: {
		LoopBlock* lb = find_loop(f, L);
		if (lb && lb->kind == O_DO) {   // tail of do ... while
			double c = eval_rest(b.o_rest, true, present);
			if (c != 0) {
				count(lb);
				pc = lb->start + 1;
			} else {
				pop_to(f, lb);
			}
			break;
		}
		double c = eval_rest(b.o_rest, true, present);
		if (lb && lb->kind == O_WHILE && lb->start == pc - 1) {
			count(lb);
		} else {
			if (f.loops.size() >= 1000)
				fail("Too many nested loops");
			f.loops.push_back(LoopBlock{O_WHILE, L, pc - 1});
			lb = &f.loops.back();
		}
		if (c == 0) {
			pop_to(f, lb);
			pc = scan(L, {O_ENDWHILE}, pc, false) + 1;
		}
		break;
	}
	case O_ENDWHILE: {
		LoopBlock* lb = find_loop(f, L);
		if (!lb || lb->kind != O_WHILE)
			fail("%s endwhile without a matching while", show(L).c_str());
		while (&f.loops.back() != lb)
			f.loops.pop_back();
		pc = lb->start;
		break;
	}
	case O_DO:
		eval_rest(b.o_rest, false, present);
		if (f.loops.size() >= 1000)
			fail("Too many nested loops");
		f.loops.push_back(LoopBlock{O_DO, L, pc - 1});
		break;
	case O_REPEAT: {
		double n = eval_rest(b.o_rest, true, present);
		if (f.loops.size() >= 1000)
			fail("Too many nested loops");
		LoopBlock lb{O_REPEAT, L, pc - 1};
		lb.remaining = !(n >= 0.5) ? 0 : n > 4e18 ? (long)4e18 : (long)std::nearbyint(n);
		if (lb.remaining <= 0)
			pc = scan(L, {O_ENDREPEAT}, pc, false) + 1;
		else
			f.loops.push_back(lb);
		break;
	}
	case O_ENDREPEAT: {
		LoopBlock* lb = find_loop(f, L);
		if (!lb || lb->kind != O_REPEAT)
			fail("%s endrepeat without a matching repeat", show(L).c_str());
		while (&f.loops.back() != lb)
			f.loops.pop_back();
		count(lb);
		if (--lb->remaining > 0)
			pc = lb->start + 1;
		else
			f.loops.pop_back();
		break;
	}
	case O_BREAK:
	case O_CONTINUE: {
		LoopBlock* lb = find_loop(f, L);
		if (!lb)
			fail("%s %s outside a loop with that label", show(L).c_str(), kind_name(b.o));
		while (&f.loops.back() != lb)
			f.loops.pop_back();
		OKind end = lb->kind == O_WHILE ? O_ENDWHILE : lb->kind == O_DO ? O_WHILE : O_ENDREPEAT;
		size_t j = scan(L, {end}, pc, false);
		if (b.o == O_BREAK) {
			f.loops.pop_back();
			pc = j + 1;
		} else {
			pc = lb->kind == O_WHILE ? lb->start : j;
		}
		break;
	}
	default:
		fail("Unknown o-word statement");
	}
}

void Interp::Impl::call_sub(const std::string& label, const std::vector<double>& args)
{
	if ((int)frames.size() > MAX_CALL_DEPTH)
		fail("Too many subroutine levels");
	auto it = subs.find(label);
	if (it == subs.end() && label[0] == '<') {
		std::string name = label.substr(1, label.size() - 2);
		for (const auto& dir : cfg.subroutine_path) {
			std::string path = dir + "/" + name + ".ngc";
			int idx;
			auto f = sub_files.find(path);
			if (f != sub_files.end()) {
				idx = f->second;
			} else {
				std::ifstream in(path);
				if (!in)
					continue;
				auto s = std::make_unique<Source>();
				s->name = path;
				std::string line;
				while (std::getline(in, line)) {
					if (s->lines.size() >= cfg.max_file_lines)
						fail("%s: more than %zu lines", path.c_str(), cfg.max_file_lines);
					s->lines.push_back(line);
				}
				sources.push_back(std::move(s));
				idx = (int)sources.size() - 1;
				sub_files[path] = idx;
			}
			const Source& s = *sources[idx];
			for (size_t i = 0; i < s.lines.size(); i++) {
				std::string lab;
				OKind k;
				if (o_header(s.lines[i], lab, k) && k == O_SUB && lab == label) {
					subs[label] = SubDef{idx, i};
					break;
				}
			}
			it = subs.find(label);
			if (it == subs.end())
				fail("File %s does not define %s", path.c_str(), show(label).c_str());
			break;
		}
		if (it == subs.end())
			fail("Unable to find subroutine file %s.ngc for %s call", name.c_str(), show(label).c_str());
	}
	if (it == subs.end())
		fail("Unknown oword number");
	Frame fr;
	fr.label = label;
	fr.ret_src = src;
	fr.ret_pc = pc;
	for (int k = 0; k < MAX_SUB_ARGS; k++)
		fr.saved_args[k] = params[k + 1];
	for (size_t k = 0; k < args.size(); k++)
		params[k + 1] = args[k];
	globals["_value"] = 0;
	globals["_value_returned"] = 0;
	frames.push_back(std::move(fr));
	src = it->second.src;
	pc = it->second.line + 1;
}

void Interp::Impl::return_sub(bool has_value, double value)
{
	Frame fr = std::move(frames.back());
	frames.pop_back();
	for (int k = 0; k < MAX_SUB_ARGS; k++)
		params[k + 1] = fr.saved_args[k];
	if (fr.m73)
		restore_modal(*fr.m73);
	src = fr.ret_src;
	pc = fr.ret_pc;
	if (has_value) {
		globals["_value"] = value;
		globals["_value_returned"] = 1;
	}
}

// gcode.md 6: a program uses o-word subroutines or Fanuc-style ones, not both.
static const char mix_error[] = "Cannot mix Fanuc-style (M98/M99) and o-word (sub/call) subroutines in one program";

void Interp::Impl::sub_style_is(int style)
{
	if (sub_style != 0 && sub_style != style)
		fail("%s", mix_error);
	sub_style = style;
}

size_t Interp::Impl::fanuc_find_m99(size_t from, const std::string& label)
{
	const Source& s = *sources[src];
	std::string key = "m99|" + std::to_string(from);
	auto c = sources[src]->scan_cache.find(key);
	if (c != s.scan_cache.end())
		return c->second;
	for (size_t i = from; i < s.lines.size(); i++) {
		std::string lab;
		OKind k;
		if (o_header(s.lines[i], lab, k) && k == O_FANUC) {
			cur_line = (int)i + 1;
			fail("%s starts before the M99 of %s", show(lab).c_str(), show(label).c_str());
		}
		if (has_m99(s.lines[i])) {
			if (sources[src]->scan_cache.size() < 100000)
				sources[src]->scan_cache[key] = i;
			return i;
		}
	}
	fail("No M99 found for %s", show(label).c_str());
}

// M98 P<n> [L<count>]: runs O<n> (of the same file) count times; #1-#30 stay global.
void Interp::Impl::fanuc_call(const Block& b)
{
	if (!b.w('p'))
		fail("P word missing with M98");
	double pv = b.v('p');
	if (pv < 0 || std::fabs(pv - std::nearbyint(pv)) > 0.0001 || pv > 99999999)
		fail("P value with M98 must be a non-negative integer program number");
	long count = b.w('l') ? std::lround(b.v('l')) : 1;
	sub_style_is(2);
	if (count == 0)
		return;
	if ((int)frames.size() > MAX_CALL_DEPTH)
		fail("Too many subroutine levels");
	std::string label = std::to_string(std::lround(pv));
	Source& s = *sources[src];
	std::string key = "o|" + label;
	size_t at;
	auto c = s.scan_cache.find(key);
	if (c != s.scan_cache.end()) {
		at = c->second;
	} else {
		at = s.lines.size();
		for (size_t i = 0; i < s.lines.size() && at == s.lines.size(); i++) {
			std::string lab;
			OKind k;
			if (o_header(s.lines[i], lab, k) && k == O_FANUC && lab == label)
				at = i;
		}
		if (at == s.lines.size())
			fail("Unknown program number %s for M98", show(label).c_str());
		if (s.scan_cache.size() < 100000)
			s.scan_cache[key] = at;
	}
	Frame fr;
	fr.label = label;
	fr.fanuc = true;
	fr.fanuc_left = count;
	fr.fanuc_start = at;
	fr.ret_src = src;
	fr.ret_pc = pc;
	frames.push_back(std::move(fr));
	pc = at + 1;
}

// M99: the end of one run of a subprogram (again while M98's L count lasts), or, in
// the main program, a jump back to its start (an endless program; in MDI nothing).
void Interp::Impl::fanuc_return()
{
	if (frames.size() > 1) {
		Frame& f = frames.back();
		if (!f.fanuc)
			fail("%s", mix_error);   // M99 inside an o-word subroutine
		if (--f.fanuc_left > 0) {
			pc = f.fanuc_start + 1;
			return;
		}
		Frame fr = std::move(frames.back());
		frames.pop_back();
		if (fr.m73)
			restore_modal(*fr.m73);
		src = fr.ret_src;
		pc = fr.ret_pc;
		return;
	}
	if (src == mdi_src)
		return;
	sub_style_is(2);
	if (cfg.max_m99_restarts >= 0 && m99_restarts >= cfg.max_m99_restarts) {
		comp_flush();
		ended = true;
		return;
	}
	m99_restarts++;
	pc = restart_pc;
	main_started = false;
}

}  // namespace rs274
