// SPDX-License-Identifier: GPL-2.0-or-later
// Config::from_ini: the INI keys the interpreter reads (ini-and-launch.md 2.5), relative
// paths, and the file:line message for a bad value.
#include <fstream>

#include "interp_test_util.hpp"

namespace {

// A directory of its own per test (ctest runs the tests as parallel processes), removed
// at the end; write() puts an INI file there.
struct IniDir {
	std::string dir = ::testing::TempDir() + "interp_config." +
	                  ::testing::UnitTest::GetInstance()->current_test_info()->name();
	IniDir()
	{
		std::string mk = "mkdir -p " + dir;
		EXPECT_EQ(system(mk.c_str()), 0);
	}
	~IniDir()
	{
		std::string rm = "rm -rf " + dir;
		EXPECT_EQ(system(rm.c_str()), 0);
	}
	std::string write(const std::string& text, const std::string& name = "m.ini") const
	{
		std::ofstream(dir + "/" + name) << text;
		return dir + "/" + name;
	}
};

}   // namespace

TEST(InterpConfig, KeysAndRelativePaths)
{
	IniDir d;
	std::string path = d.write("[TRAJ]\nLINEAR_UNITS = inch\nCOORDINATES = x Y z a\n"
	                           "[RS274NGC]\nPARAMETER_FILE = sim.var\nSUBROUTINE_PATH = subs: /abs/s\n"
	                           "ORIENT_OFFSET = 12.5\nDISABLE_FANUC_STYLE_SUB = 1\n"
	                           "[DISPLAY]\nPROGRAM_PREFIX = nc\n"
	                           "[EMCIO]\nTOOL_TABLE = /t/tool.tbl\nRANDOM_TOOLCHANGER = 1\n");
	const std::string& dir = d.dir;
	rs274::Config c;
	std::string err;
	ASSERT_TRUE(rs274::Config::from_ini(path, c, err)) << err;
	EXPECT_EQ(c.machine_units, rs274::Units::INCH);
	EXPECT_EQ(c.axes, "XYZA");
	EXPECT_EQ(c.parameter_file, dir + "/sim.var");
	EXPECT_EQ(c.subroutine_path, (std::vector<std::string>{dir + "/nc", dir + "/subs", "/abs/s"}));
	EXPECT_EQ(c.user_m_path, (std::vector<std::string>{dir + "/nc"}));
	EXPECT_EQ(c.orient_offset, 12.5);
	EXPECT_TRUE(c.disable_fanuc_style_sub);
	EXPECT_EQ(c.tool_table, "/t/tool.tbl");
	EXPECT_TRUE(c.random_toolchanger);
	EXPECT_EQ(c.ini.at("TRAJ]COORDINATES"), "x Y z a");
}

TEST(InterpConfig, BadCoordinatesLetterNamesFileAndLine)
{
	IniDir d;
	std::string path = d.write("[TRAJ]\nLINEAR_UNITS = mm\nCOORDINATES = X Y Q\n");
	rs274::Config c;
	std::string err;
	EXPECT_FALSE(rs274::Config::from_ini(path, c, err));
	EXPECT_EQ(err, path + ":3: [TRAJ]COORDINATES: 'Q' is not one of X Y Z A B C U V W");
}

TEST(InterpConfig, BadUnitsAndNumbers)
{
	IniDir d;
	rs274::Config c;
	std::string err;
	std::string path = d.write("[TRAJ]\nLINEAR_UNITS = furlong\n");
	EXPECT_FALSE(rs274::Config::from_ini(path, c, err));
	EXPECT_EQ(err, path + ": [TRAJ]LINEAR_UNITS must be mm or inch: furlong");
	EXPECT_FALSE(rs274::Config::from_ini(d.write("[RS274NGC]\nORIENT_OFFSET = ten\n", "n.ini"), c, err));
	EXPECT_NE(err.find(":2:"), std::string::npos) << err;
	EXPECT_NE(err.find("ORIENT_OFFSET"), std::string::npos) << err;
	EXPECT_FALSE(rs274::Config::from_ini(d.dir + "/no-such.ini", c, err));
	EXPECT_NE(err.find("no-such.ini"), std::string::npos) << err;
}
