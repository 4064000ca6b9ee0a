// SPDX-License-Identifier: GPL-2.0-or-later
// hal_module.cpp - the Python 'hal' module: LinuxCNC's Python interface to HAL
// (userspace components in Python, and scripts that inspect and wire the HAL),
// built on the ULAPI library that halcmd uses. Constants, the hal.error exception
// and the flavor flags live here; hal_component.cpp and hal_functions.cpp hold
// the rest.
#include <pybind11/pybind11.h>

#include "hal_component.hpp"
#include "hal_errors.hpp"
#include "hal_functions.hpp"

extern "C" {
#include "hal.h"
// kernel/rtapi/rtapi_shmem_ulapi_kmod.c: whether this process's ULAPI reaches the
// kernel flavor's segments (/dev/rtapi) or the simulated flavor's. Asked, not
// re-derived, so the flags below always describe the HAL this module talks to.
int rtapi_shmem_kmod_active(void);
}

namespace pyb = pybind11;
using namespace hal::py;

PYBIND11_MODULE(hal, m)
{
    m.doc() = "Interface to the HAL: userspace components written in Python and HAL queries";

    pyb::register_exception<HalError>(m, "error", PyExc_RuntimeError);

    m.attr("HAL_BIT") = static_cast<int>(HAL_BIT);
    m.attr("HAL_FLOAT") = static_cast<int>(HAL_FLOAT);
    m.attr("HAL_S32") = static_cast<int>(HAL_S32);
    m.attr("HAL_U32") = static_cast<int>(HAL_U32);
    m.attr("HAL_S64") = static_cast<int>(HAL_S64);
    m.attr("HAL_U64") = static_cast<int>(HAL_U64);
    m.attr("HAL_IN") = static_cast<int>(HAL_IN);
    m.attr("HAL_OUT") = static_cast<int>(HAL_OUT);
    m.attr("HAL_IO") = static_cast<int>(HAL_IO);
    m.attr("HAL_RO") = static_cast<int>(HAL_RO);
    m.attr("HAL_RW") = static_cast<int>(HAL_RW);
    m.attr("MSG_NONE") = static_cast<int>(RTAPI_MSG_NONE);
    m.attr("MSG_ERR") = static_cast<int>(RTAPI_MSG_ERR);
    m.attr("MSG_WARN") = static_cast<int>(RTAPI_MSG_WARN);
    m.attr("MSG_INFO") = static_cast<int>(RTAPI_MSG_INFO);
    m.attr("MSG_DBG") = static_cast<int>(RTAPI_MSG_DBG);
    m.attr("MSG_ALL") = static_cast<int>(RTAPI_MSG_ALL);

    // LinuxCNC's flags are attributes (if hal.is_sim: ...). The simulated flavor runs
    // realtime code in a userspace process (rtapi_app) without a realtime guarantee;
    // the kernel flavor runs it in the kernel.
    bool kernel = rtapi_shmem_kmod_active() != 0;
    m.attr("is_kernelspace") = kernel;
    m.attr("is_userspace") = !kernel;
    m.attr("is_rt") = kernel;
    m.attr("is_sim") = !kernel;

    register_component(m);
    register_functions(m);

    // Components still alive when the interpreter ends leave the HAL with it,
    // whatever order module teardown destroys objects in.
    m.def("_exit_all_components", &exit_all_components);
    pyb::module_::import("atexit").attr("register")(m.attr("_exit_all_components"));
}
