// SPDX-License-Identifier: GPL-2.0-or-later
// rs274 - read a G-code program and print the canonical machining calls it makes,
// one per line (format: print_canon.hpp, docs/interp.md). Exit status 0 when the
// program ends (M2/M30/%), 1 with "file:line: message" on stderr on an error, 2 on a
// usage error.
#include <getopt.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>

#include "rs274/interp.hpp"
#include "rs274/print_canon.hpp"

static void usage(std::FILE* f)
{
	std::fputs(
	    "usage: rs274 [options] FILE\n"
	    "Interpret the RS274NGC (G-code) program FILE ('-' = standard input) without a machine\n"
	    "and print every canonical call it makes, one per line: LINE NAME(args).\n"
	    "Positions are machine coordinates in machine units, after all offsets.\n"
	    "  -i, --ini FILE         read [RS274NGC] (PARAMETER_FILE, RS274NGC_STARTUP_CODE,\n"
	    "                         SUBROUTINE_PATH, USER_M_PATH, ORIENT_OFFSET,\n"
	    "                         CENTER_ARC_RADIUS_TOLERANCE_*), [TRAJ] (LINEAR_UNITS,\n"
	    "                         COORDINATES), [DISPLAY]PROGRAM_PREFIX and [EMCIO] keys\n"
	    "  -t, --tool-table FILE  tool table (overrides [EMCIO]TOOL_TABLE)\n"
	    "  -p, --parameters FILE  parameter file, read at start and written back at the end\n"
	    "                         (overrides [RS274NGC]PARAMETER_FILE)\n"
	    "  -s, --startup CODE     G-code run before the program (overrides RS274NGC_STARTUP_CODE)\n"
	    "  -b, --block-delete     skip lines that start with '/'\n"
	    "  -n, --no-save          do not write the parameter file back\n"
	    "  -r, --m99-restarts N   M99 in the main program restarts it N times, then ends it\n"
	    "                         (default 0: the program runs once; -1: endless)\n"
	    "  -h, --help             this text\n"
	    "Exit status: 0 program ended (M2, M30 or closing %), 1 error (file:line: message on\n"
	    "standard error), 2 bad usage.\n",
	    f);
}

int main(int argc, char** argv)
{
	static const option longopts[] = {
		{"ini", required_argument, nullptr, 'i'},
		{"tool-table", required_argument, nullptr, 't'},
		{"parameters", required_argument, nullptr, 'p'},
		{"startup", required_argument, nullptr, 's'},
		{"block-delete", no_argument, nullptr, 'b'},
		{"no-save", no_argument, nullptr, 'n'},
		{"m99-restarts", required_argument, nullptr, 'r'},
		{"help", no_argument, nullptr, 'h'},
		{nullptr, 0, nullptr, 0},
	};
	const char *ini = nullptr, *tools = nullptr, *params = nullptr, *startup = nullptr;
	bool block_delete = false, save = true;
	long restarts = 0;
	int c;
	while ((c = getopt_long(argc, argv, "i:t:p:s:r:bnh", longopts, nullptr)) != -1) {
		switch (c) {
		case 'i': ini = optarg; break;
		case 't': tools = optarg; break;
		case 'p': params = optarg; break;
		case 's': startup = optarg; break;
		case 'b': block_delete = true; break;
		case 'n': save = false; break;
		case 'r': {
			char* e;
			restarts = std::strtol(optarg, &e, 10);
			if (*e || e == optarg || restarts < -1) {
				std::fprintf(stderr, "rs274: -r needs a number of restarts (-1 = endless): %s\n", optarg);
				return 2;
			}
			break;
		}
		case 'h': usage(stdout); return 0;
		default: usage(stderr); return 2;
		}
	}
	if (optind != argc - 1) {
		usage(stderr);
		return 2;
	}
	const char* file = argv[optind];
	rs274::Config cfg;
	std::string err;
	if (ini && !rs274::Config::from_ini(ini, cfg, err)) {
		std::fprintf(stderr, "rs274: %s\n", err.c_str());
		return 1;
	}
	if (tools)
		cfg.tool_table = tools;
	if (params)
		cfg.parameter_file = params;
	if (startup)
		cfg.startup_code = startup;
	cfg.max_m99_restarts = restarts;

	std::ios::sync_with_stdio(false);
	rs274::PrintCanon canon(std::cout, cfg.axes);
	rs274::Interp interp(canon, cfg);
	interp.set_block_delete(block_delete);
	bool ok = interp.init();
	if (ok) {
		if (std::strcmp(file, "-") == 0) {
			std::stringstream ss;
			ss << std::cin.rdbuf();
			ok = interp.open_text("stdin", ss.str());
		} else {
			ok = interp.open(file);
		}
	}
	if (ok)
		ok = interp.run() == rs274::Status::END;
	std::cout.flush();
	int status = 0;
	if (!ok) {
		std::fprintf(stderr, "%s\n", interp.error().to_string().c_str());
		status = 1;
	}
	if (save && !interp.save_parameters()) {
		std::fprintf(stderr, "rs274: %s\n", interp.error().to_string().c_str());
		status = 1;
	}
	return status;
}
