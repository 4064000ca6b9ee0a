// SPDX-License-Identifier: GPL-2.0-or-later
// input_udev.cpp - scan_input_devices() with libudev.
#include "input_udev.hpp"

#include <libudev.h>

#include <cstdlib>
#include <memory>
#include <string>

namespace hal::input {

namespace {

struct UdevUnref { void operator()(udev* u) const { udev_unref(u); } };
struct EnumUnref { void operator()(udev_enumerate* e) const { udev_enumerate_unref(e); } };
struct DevUnref { void operator()(udev_device* d) const { udev_device_unref(d); } };

std::string attr(udev_device* d, const char* name)
{
    const char* v = udev_device_get_sysattr_value(d, name);
    return v ? v : "";
}

unsigned hex_attr(udev_device* d, const char* name)
{
    return static_cast<unsigned>(std::strtoul(attr(d, name).c_str(), nullptr, 16));
}

}  // namespace

std::vector<DeviceInfo> scan_input_devices()
{
    std::vector<DeviceInfo> out;
    std::unique_ptr<udev, UdevUnref> u{udev_new()};
    if (!u)
        return out;
    std::unique_ptr<udev_enumerate, EnumUnref> en{udev_enumerate_new(u.get())};
    if (!en)
        return out;
    udev_enumerate_add_match_subsystem(en.get(), "input");
    udev_enumerate_add_match_sysname(en.get(), "event*");
    udev_enumerate_scan_devices(en.get());
    udev_list_entry* entry;
    udev_list_entry_foreach(entry, udev_enumerate_get_list_entry(en.get()))
    {
        std::unique_ptr<udev_device, DevUnref> dev{
            udev_device_new_from_syspath(u.get(), udev_list_entry_get_name(entry))};
        if (!dev)
            continue;
        DeviceInfo info;
        std::string sysname = udev_device_get_sysname(dev.get());
        info.event_number = std::atoi(sysname.c_str() + 5);     // "eventN"
        const char* node = udev_device_get_devnode(dev.get());
        info.devnode = node ? node : "/dev/input/" + sysname;
        // the parent "inputN" device carries name, phys and id (not a new reference)
        udev_device* parent = udev_device_get_parent_with_subsystem_devtype(dev.get(), "input", nullptr);
        if (parent) {
            info.name = attr(parent, "name");
            info.phys = attr(parent, "phys");
            info.id = format_id(hex_attr(parent, "id/bustype"), hex_attr(parent, "id/vendor"),
                                hex_attr(parent, "id/product"), hex_attr(parent, "id/version"));
        }
        out.push_back(info);
    }
    return out;
}

}  // namespace hal::input
