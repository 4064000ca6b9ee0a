// SPDX-License-Identifier: GPL-2.0-or-later
// meter_source.cpp - reading one HAL item for halmeter; see meter_source.hpp.
#include "meter_source.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

#include "hal/kmod.hpp"
#include "hal_query.h"
#include "rtapi_client.hpp"
#include "values.hpp"

namespace hal::meter {

// hal_attach() makes the HAL when none exists (a new segment in the simulated
// flavor; hal_lib.ko loaded in the kernel flavor): an observer must first see that
// a session runs, or it would leave a HAL of its own behind.
Result<void> attach_hal()
{
    auto flavor = kmod::detect_flavor();
    if (!flavor)
        return Error{flavor.error().code, flavor.error().message};
    setenv("HAL_FLAVOR", kmod::flavor_name(flavor->flavor), 1);   // the ULAPI library follows it
    bool running = flavor->flavor == kmod::Flavor::kmod ? kmod::module_loaded("hal_lib") : rtapi_running();
    if (!running)
        return Error{-ENOENT, std::string("no HAL session is running (") + kmod::flavor_name(flavor->flavor) +
                                  " flavor" + (flavor->flavor == kmod::Flavor::kmod ? "" :
                                  ", RTAPI_INSTANCE=" + std::string(std::getenv("RTAPI_INSTANCE") ?
                                  std::getenv("RTAPI_INSTANCE") : "0")) +
                                  "): start one with halrun or halcmd first"};
    int rc = hal_attach();
    if (rc < 0)
        return Error{rc, "cannot attach to the HAL (is a HAL session running?)"};
    return ok();
}

Result<std::string> read_item(const Item& item)
{
    const char* n = item.name.c_str();
    switch (item.kind) {
    case Kind::pin: {
        hal_pin_info p;
        if (hal_find_pin(n, &p) == 0)
            return halcmd::format_value(p.type, p.value);
        break;
    }
    case Kind::sig: {
        hal_sig_info s;
        if (hal_find_sig(n, &s) == 0)
            return halcmd::format_value(s.type, s.value);
        break;
    }
    case Kind::param: {
        hal_param_info p;
        if (hal_find_param(n, &p) == 0)
            return halcmd::format_value(p.type, p.value);
        break;
    }
    case Kind::none:
        return Error{-22, "nothing selected"};
    }
    const char* what = item.kind == Kind::pin ? "pin" : item.kind == Kind::sig ? "signal" : "parameter";
    return Error{-2, std::string(what) + " '" + item.name + "' does not exist"};
}

namespace {

template <typename Info>
int collect(const Info* info, void* ctx)
{
    static_cast<std::vector<std::string>*>(ctx)->push_back(info->name);
    return 0;
}

}  // namespace

std::vector<std::string> list_names(Kind kind)
{
    std::vector<std::string> names;
    if (kind == Kind::pin)
        hal_query_pins(collect<hal_pin_info>, &names);
    else if (kind == Kind::sig)
        hal_query_sigs(collect<hal_sig_info>, &names);
    else if (kind == Kind::param)
        hal_query_params(collect<hal_param_info>, &names);
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace hal::meter
