// SPDX-License-Identifier: GPL-2.0-or-later
// interp.cpp - the public Interp: program sources, stepping line by line, MDI, init
// (parameter file, tool table, startup code), errors with file:line; Config from INI.
#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>

#include "impl.hpp"
#include "ini/axes.hpp"

namespace rs274 {

const char* plane_name(Plane p)
{
	switch (p) {
	case Plane::XY: return "CANON_PLANE_XY";
	case Plane::YZ: return "CANON_PLANE_YZ";
	case Plane::XZ: return "CANON_PLANE_XZ";
	case Plane::UV: return "CANON_PLANE_UV";
	case Plane::VW: return "CANON_PLANE_VW";
	default: return "CANON_PLANE_UW";
	}
}

const char* units_name(Units u) { return u == Units::MM ? "CANON_UNITS_MM" : "CANON_UNITS_INCHES"; }

const char* feed_mode_name(FeedMode m)
{
	return m == FeedMode::UNITS_PER_MINUTE ? "UNITS_PER_MINUTE"
	     : m == FeedMode::INVERSE_TIME ? "INVERSE_TIME" : "UNITS_PER_REVOLUTION";
}

const char* motion_control_name(MotionControl m)
{
	return m == MotionControl::EXACT_STOP ? "CANON_EXACT_STOP"
	     : m == MotionControl::EXACT_PATH ? "CANON_EXACT_PATH" : "CANON_CONTINUOUS";
}

std::string Error::to_string() const
{
	if (file.empty())
		return message;
	return file + ":" + std::to_string(line) + ": " + message;
}

Interp::Impl::Impl(Canon& c, Config conf) : canon(c), cfg(std::move(conf))
{
	params.assign(MAX_PARAM, 0);
	param_in_file.assign(MAX_PARAM, 0);
	for (char l : cfg.axes) {
		int a = hal::ini::axis_index(l);
		if (a >= 0)
			axis_on[a] = true;
	}
	units = cfg.machine_units;
	frames.emplace_back();
}

Interp::Interp(Canon& canon, Config cfg) : impl_(std::make_unique<Impl>(canon, std::move(cfg))) {}

Interp::~Interp()
{
	if (impl_->log_file)
		std::fclose(impl_->log_file);
	if (impl_->probe_file)
		std::fclose(impl_->probe_file);
}

bool Interp::init()
{
	Impl& s = *impl_;
	try {
		s.load_param_file();
		double c = s.params[5220];
		s.coord = c >= 1 && c <= 9 ? (int)c : 1;
		s.params[5220] = s.coord;
		if (s.cfg.disable_g92_persistence)
			for (int i = 5210; i <= 5219; i++)
				s.params[i] = 0;
		if (s.params[5210] == 1)
			for (int a = 0; a < NUM_AXES; a++)
				s.g92[a] = s.axis_on[a] ? s.params[5211 + a] : 0;
		s.params[5599] = 1;
		s.load_tool_table();
		s.canon.block_begin("", 0);
		s.report_offsets();
	} catch (const InterpError& e) {
		s.err = Error{"", 0, e.message};
		return false;
	}
	if (!s.cfg.startup_code.empty() && execute_mdi(s.cfg.startup_code) == Status::ERROR) {
		s.err.file = "RS274NGC_STARTUP_CODE";
		return false;
	}
	return true;
}

bool Interp::open(const std::string& path)
{
	std::ifstream in(path);
	if (!in) {
		impl_->err = Error{"", 0, "Unable to open file " + path};
		return false;
	}
	std::stringstream ss;
	ss << in.rdbuf();
	return open_text(path, ss.str());
}

bool Interp::open_text(const std::string& name, const std::string& text)
{
	Impl& s = *impl_;
	auto src = std::make_unique<Source>();
	src->name = name;
	size_t start = 0;
	while (start < text.size()) {
		size_t nl = text.find('\n', start);
		if (nl == std::string::npos)
			nl = text.size();
		if (src->lines.size() >= s.cfg.max_file_lines) {
			s.err = Error{name, (int)src->lines.size(), "program has too many lines"};
			return false;
		}
		src->lines.push_back(text.substr(start, nl - start));
		start = nl + 1;
	}
	reset();
	s.subs.clear();
	s.sources.push_back(std::move(src));
	s.main_src = s.src = (int)s.sources.size() - 1;
	s.pc = 0;
	s.percent_mode = s.seen_first = s.ended = false;
	s.blocks = 0;
	s.restart_pc = 0;
	s.m99_restarts = 0;
	s.main_started = false;
	s.sub_style = 0;
	return true;
}

static bool percent_line(const std::string& l)
{
	for (char c : l) {
		if (c == ' ' || c == '\t' || c == '\r')
			continue;
		return c == '%';
	}
	return false;
}

static bool blank_line(const std::string& l)
{
	for (char c : l)
		if (c != ' ' && c != '\t' && c != '\r')
			return false;
	return true;
}

Status Interp::step()
{
	Impl& s = *impl_;
	if (s.src < 0) {
		s.err = Error{"", 0, "No program open"};
		return Status::ERROR;
	}
	if (s.ended)
		return Status::END;
	Source* so = s.sources[s.src].get();
	try {
		if (s.pc >= so->lines.size()) {
			s.cur_line = (int)so->lines.size();
			if (s.src != s.main_src)
				fail("File ended inside subroutine %s (no endsub)", ("o" + s.frames.back().label).c_str());
			if (s.percent_mode)
				fail("File ended with no percent sign (%%)");
			fail("File ended with no percent sign (%%) or program end (M2)");
		}
		size_t idx = s.pc++;
		s.cur_line = (int)idx + 1;
		const std::string& raw = so->lines[idx];
		if (s.src == s.main_src && so->name != "MDI") {
			if (percent_line(raw)) {
				if (!s.seen_first) {
					s.seen_first = s.percent_mode = true;
					s.restart_pc = idx + 1;
					return Status::OK;
				}
				s.comp_flush();
				s.ended = true;
				return Status::END;
			}
			if (!blank_line(raw))
				s.seen_first = true;
		}
		s.canon.block_begin(so->name, s.cur_line);
		Block b = s.read_block(raw, s.cur_line);
		if (b.empty)
			return Status::OK;
		for (const auto& [i, v] : b.num_sets)
			s.set_param(i, v);
		for (const auto& [n, v] : b.name_sets)
			s.set_named(n, v);
		if (b.o != O_NONE)
			s.execute_o(b);
		else
			s.execute_block(b);
	} catch (const InterpError& e) {
		s.err = Error{so->name, s.cur_line, e.message};
		s.canon.drop();          // calls held behind a comp move die with the program
		s.comp_pending = false;
		return Status::ERROR;
	}
	return s.ended ? Status::END : Status::OK;
}

Status Interp::run()
{
	while (true) {
		Status st = step();
		if (st != Status::OK)
			return st;
	}
}

Status Interp::execute_mdi(const std::string& line)
{
	Impl& s = *impl_;
	if (s.mdi_src < 0) {
		s.sources.push_back(std::make_unique<Source>());
		s.mdi_src = (int)s.sources.size() - 1;
		s.sources[s.mdi_src]->name = "MDI";
	}
	int mdi = s.mdi_src;
	s.sources[mdi]->lines.assign(1, line);
	s.sources[mdi]->scan_cache.clear();
	int saved_src = s.src, saved_main = s.main_src;
	size_t saved_pc = s.pc;
	size_t base = s.frames.size();
	bool saved_ended = s.ended;
	int saved_style = s.sub_style;
	s.sub_style = 0;   // MDI calls are not part of the program's subroutine style
	s.src = mdi;
	s.main_src = mdi;
	s.pc = 0;
	s.ended = false;
	Status st = Status::OK;
	while (!(s.src == mdi && s.pc >= 1 && s.frames.size() == base)) {
		st = step();
		if (st != Status::OK)
			break;
	}
	if (st == Status::ERROR)
		s.frames.resize(base);
	s.src = saved_src;
	s.main_src = saved_main;
	s.pc = saved_pc;
	s.ended = saved_ended;
	s.sub_style = saved_style;
	return st == Status::ERROR ? Status::ERROR : Status::OK;
}

void Interp::reset()
{
	Impl& s = *impl_;
	s.frames.resize(1);
	s.frames[0].loops.clear();
	s.src = -1;
	s.ended = false;
	s.comp_pending = false;
	s.comp_exit_next = false;
	s.canon.drop();
	s.nurbs_open = false;
	s.cycle_code = -1;
}

bool Interp::save_parameters() { return impl_->cfg.parameter_file.empty() || save_parameters(impl_->cfg.parameter_file); }
bool Interp::save_parameters(const std::string& path) { return impl_->write_param_file(path); }
void Interp::set_machine_position(const Pos& p)
{
	if (!impl_->comp_pending)
		impl_->mpos = p;
}
void Interp::set_block_delete(bool on) { impl_->block_delete = on; }
void Interp::set_optional_stop(bool on) { impl_->optional_stop = on; }
const Error& Interp::error() const { return impl_->err; }
int Interp::line() const { return impl_->cur_line; }
double Interp::parameter(int index) const { return impl_->get_param(index); }

std::vector<int> Interp::active_g_codes() const
{
	const Impl& m = *impl_;
	static const int plane[] = {170, 190, 180, 171, 191, 181};   // XY YZ XZ UV VW UW
	static const int coord[] = {540, 550, 560, 570, 580, 590, 591, 592, 593};
	int mc = m.mc == MotionControl::EXACT_PATH ? 610 : m.mc == MotionControl::EXACT_STOP ? 611 : 640;
	int feed = m.feed_mode == FeedMode::INVERSE_TIME ? 930 : m.feed_mode == FeedMode::UNITS_PER_REV ? 950 : 940;
	return {m.motion,
		plane[static_cast<int>(m.plane)],
		m.comp,
		m.units == Units::INCH ? 200 : 210,
		m.incremental ? 910 : 900,
		feed,
		coord[(m.coord >= 1 && m.coord <= 9 ? m.coord : 1) - 1],
		m.tlo_mode,
		m.retract_old_z ? 980 : 990,
		mc,
		m.css ? 960 : 970,
		m.ijk_absolute ? 901 : 911,
		m.lathe_diameter ? 70 : 80};
}

std::vector<int> Interp::active_m_codes() const
{
	const Impl& m = *impl_;
	std::vector<int> v{m.spindle_dir > 0 ? 3 : m.spindle_dir < 0 ? 4 : 5};
	if (m.mist)
		v.push_back(7);
	if (m.flood)
		v.push_back(8);
	if (!m.mist && !m.flood)
		v.push_back(9);
	v.push_back(m.feed_override && m.speed_override ? 48 : 49);
	return v;
}

bool Interp::named_parameter(const std::string& name, double& value) const
{
	try {
		return impl_->get_named(name, value);
	} catch (const InterpError&) {
		return false;
	}
}

}  // namespace rs274
