// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_pci.h's driver interface in the simulated flavor over real cards' sysfs files
// (rtapi_pci_uspace.c), on a directory of the same layout (HAL_PCI_SYSFS_DIR) whose
// plain files stand in for the resource files: cards matched by all four IDs in
// address order, a memory BAR mapped (mmap), an I/O BAR read and written (pread/
// pwrite), a card locked against a second driver, a missing resource file refused.
#include <gtest/gtest.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>
#include <sys/stat.h>
#include <unistd.h>

extern "C" {
#include "rtapi.h"
#include "rtapi_pci.h"
}

namespace {

std::string dir;

void put(const std::string &path, const std::string &text)
{
	std::ofstream(path) << text;
}

void sized(const std::string &path, size_t n)
{
	std::ofstream f(path, std::ios::binary);
	f << std::string(n, '\0');
}

// a card at addr: IDs, the "resource" table (BAR1 and BAR2 I/O, BAR3 memory), files
void card(const std::string &addr, unsigned subdevice, bool with_bar3 = true)
{
	std::string d = dir + "/" + addr;
	mkdir(d.c_str(), 0755);
	put(d + "/vendor", "0x10b5\n");
	put(d + "/device", "0x9054\n");
	put(d + "/subsystem_vendor", "0x10b5\n");
	char sd[16];
	snprintf(sd, sizeof(sd), "0x%04x\n", subdevice);
	put(d + "/subsystem_device", sd);
	put(d + "/resource", "0x0 0x0 0x0\n0xe000 0xe0ff 0x101\n0xe400 0xe4ff 0x101\n"
			     "0xf0000000 0xf000ffff 0x40200\n0x0 0x0 0x0\n0x0 0x0 0x0\n");
	put(d + "/config", std::string(64, '\0'));
	put(d + "/enable", "0\n");
	sized(d + "/resource1", 256);
	sized(d + "/resource2", 256);
	if (with_bar3)
		sized(d + "/resource3", 0x10000);
}

std::vector<unsigned char> bytes(const std::string &path)
{
	std::ifstream f(path, std::ios::binary);
	return std::vector<unsigned char>(std::istreambuf_iterator<char>(f), {});
}

const rtapi_pci_id kIds[] = {{0x10B5, 0x9054, 0x10B5, 0x3315}, {0, 0, 0, 0}};

struct Seen {
	std::vector<std::string> names;
	int removes = 0;
	rtapi_pci_bar *io = nullptr, *mem = nullptr;
} seen;

int probe(rtapi_pci_dev *dev, const rtapi_pci_id *)
{
	seen.names.push_back(rtapi_pci_dev_name(dev));
	int rc = rtapi_pci_dev_map_bar(dev, 1, &seen.io);
	if (!rc)
		rc = rtapi_pci_dev_map_bar(dev, 3, &seen.mem);
	if (rc && seen.io)
		rtapi_pci_unmap_bar(seen.io);
	return rc;
}

void remove(rtapi_pci_dev *)
{
	seen.removes++;
	rtapi_pci_unmap_bar(seen.io);
	rtapi_pci_unmap_bar(seen.mem);
}

class PciSysfs : public ::testing::Test {
protected:
	void SetUp() override
	{
		char tmpl[] = "/tmp/rtapi_pci_testXXXXXX";
		ASSERT_NE(mkdtemp(tmpl), nullptr);
		dir = tmpl;
		setenv("HAL_PCI_SYSFS_DIR", dir.c_str(), 1);
		seen = Seen();
	}
	void TearDown() override
	{
		unsetenv("HAL_PCI_SYSFS_DIR");
		std::string cmd = "rm -rf '" + dir + "'";
		ASSERT_EQ(system(cmd.c_str()), 0);
	}
	rtapi_pci_driver drv = {"pci_test", kIds, probe, remove, nullptr};
};

TEST_F(PciSysfs, MatchesSubsystemIdsAndMapsMemoryAndIoBars)
{
	card("0000:02:00.0", 0x3314);	// another subsystem device: not taken
	card("0000:03:00.0", 0x3315);
	ASSERT_EQ(rtapi_pci_register_driver(&drv), 1);
	ASSERT_EQ(seen.names.size(), 1u);
	EXPECT_EQ(seen.names[0], "0000:03:00.0");
	rtapi_pci_writel(seen.mem, 0x100, 0x55AACAFE);
	EXPECT_EQ(rtapi_pci_readl(seen.mem, 0x100), 0x55AACAFEu);
	rtapi_pci_writel(seen.io, 0x6C, 0x000C0000);
	rtapi_pci_writeb(seen.io, 0x10, 0xA5);
	EXPECT_EQ(rtapi_pci_readl(seen.io, 0x6C), 0x000C0000u);
	EXPECT_EQ(rtapi_pci_readb(seen.io, 0x10), 0xA5);
	EXPECT_EQ(rtapi_pci_readl(seen.io, 0x100), ~0u);	// past the BAR
	auto io = bytes(dir + "/0000:03:00.0/resource1");
	EXPECT_EQ(io[0x6E], 0x0C);	// little-endian, through pwrite
	EXPECT_EQ(io[0x10], 0xA5);
	rtapi_pci_unregister_driver(&drv);
	EXPECT_EQ(seen.removes, 1);
	auto mem = bytes(dir + "/0000:03:00.0/resource3");
	EXPECT_EQ(mem[0x100], 0xFE);	// the mapping wrote the file
}

TEST_F(PciSysfs, ASecondDriverFindsTheCardBusy)
{
	card("0000:03:00.0", 0x3315);
	ASSERT_EQ(rtapi_pci_register_driver(&drv), 1);
	rtapi_pci_driver other = {"other", kIds, probe, remove, nullptr};
	EXPECT_EQ(rtapi_pci_register_driver(&other), -EBUSY);
	rtapi_pci_unregister_driver(&drv);
}

TEST_F(PciSysfs, AMissingResourceFileFailsTheRegistration)
{
	card("0000:03:00.0", 0x3315, false);
	EXPECT_EQ(rtapi_pci_register_driver(&drv), -EPERM);
	EXPECT_EQ(seen.removes, 0);
}

TEST_F(PciSysfs, NoCardNoProbe)
{
	EXPECT_EQ(rtapi_pci_register_driver(&drv), 0);
	rtapi_pci_unregister_driver(&drv);
	EXPECT_TRUE(seen.names.empty());
}

}  // namespace
