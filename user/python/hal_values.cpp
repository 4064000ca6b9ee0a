// SPDX-License-Identifier: GPL-2.0-or-later
// hal_values.cpp - see hal_values.hpp.
#include "hal_values.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "values.hpp"   // halcmd's type names

namespace hal::py {

namespace {

std::string describe(hal_type_t type, const std::string& what)
{
    return std::string(hal::halcmd::type_name(type)) + " " + what;
}

// Any Python int, bool or float, as an integer in [lo, hi]. Floats truncate toward
// zero, as int() does.
template <typename T>
T integer_in_range(pyb::handle obj, hal_type_t type, const std::string& what)
{
    if (!PyLong_Check(obj.ptr()) && !PyFloat_Check(obj.ptr()) && !PyIndex_Check(obj.ptr()))
        throw pyb::type_error(describe(type, what) + ": expected an integer, got " +
                              std::string(Py_TYPE(obj.ptr())->tp_name));
    pyb::object as_int;
    if (PyFloat_Check(obj.ptr())) {
        double d = PyFloat_AsDouble(obj.ptr());
        if (!std::isfinite(d))
            throw pyb::value_error(describe(type, what) + ": " + pyb::str(obj).cast<std::string>() +
                                   " is not an integer");
        as_int = pyb::reinterpret_steal<pyb::object>(PyLong_FromDouble(std::trunc(d)));
    } else {
        as_int = pyb::reinterpret_steal<pyb::object>(PyNumber_Index(obj.ptr()));
    }
    if (!as_int)
        throw pyb::error_already_set();
    int overflow = 0;
    long long n = PyLong_AsLongLongAndOverflow(as_int.ptr(), &overflow);
    if (n == -1 && PyErr_Occurred())
        throw pyb::error_already_set();
    bool fits;
    T out{};
    if constexpr (std::is_same_v<T, unsigned long long>) {
        // u64 reaches beyond long long
        if (overflow > 0) {
            unsigned long long u = PyLong_AsUnsignedLongLong(as_int.ptr());
            fits = !(u == static_cast<unsigned long long>(-1) && PyErr_Occurred());
            PyErr_Clear();
            out = u;
        } else {
            fits = overflow == 0 && n >= 0;
            out = static_cast<unsigned long long>(n);
        }
    } else {
        fits = overflow == 0 && n >= static_cast<long long>(std::numeric_limits<T>::min()) &&
               n <= static_cast<long long>(std::numeric_limits<T>::max());
        out = static_cast<T>(n);
    }
    if (!fits)
        throw pyb::value_error(describe(type, what) + ": " + pyb::str(as_int).cast<std::string>() +
                               " is out of range (" +
                               std::to_string(std::numeric_limits<T>::min()) + " to " +
                               std::to_string(std::numeric_limits<T>::max()) + ")");
    return out;
}

}  // namespace

bool type_valid(int type)
{
    return type == HAL_BIT || type == HAL_FLOAT || type == HAL_S32 || type == HAL_U32 ||
           type == HAL_S64 || type == HAL_U64;
}

hal_value to_hal(hal_type_t type, pyb::handle obj, const std::string& what)
{
    hal_value v{};
    switch (type) {
    case HAL_BIT:
        // Numbers only: a string such as "0" would otherwise be true.
        if (!PyBool_Check(obj.ptr()) && !PyLong_Check(obj.ptr()) && !PyFloat_Check(obj.ptr()))
            throw pyb::type_error(describe(type, what) + ": expected a bool or a number, got " +
                                  std::string(Py_TYPE(obj.ptr())->tp_name));
        v.b = PyObject_IsTrue(obj.ptr()) == 1;
        return v;
    case HAL_FLOAT: {
        if (!PyFloat_Check(obj.ptr()) && !PyLong_Check(obj.ptr()))
            throw pyb::type_error(describe(type, what) + ": expected a number, got " +
                                  std::string(Py_TYPE(obj.ptr())->tp_name));
        double d = PyFloat_AsDouble(obj.ptr());
        if (d == -1.0 && PyErr_Occurred())
            throw pyb::error_already_set();   // an int too large for a double: OverflowError
        v.f = d;
        return v;
    }
    case HAL_S32:
        v.s = integer_in_range<int32_t>(obj, type, what);
        return v;
    case HAL_U32:
        v.u = integer_in_range<uint32_t>(obj, type, what);
        return v;
    case HAL_S64:
        v.ls = integer_in_range<long long>(obj, type, what);
        return v;
    case HAL_U64:
        v.lu = integer_in_range<unsigned long long>(obj, type, what);
        return v;
    default:
        throw pyb::value_error(what + ": invalid HAL type " + std::to_string(static_cast<int>(type)));
    }
}

pyb::object from_hal(hal_type_t type, const hal_value& v)
{
    switch (type) {
    case HAL_BIT: return pyb::bool_(v.b);
    case HAL_FLOAT: return pyb::float_(v.f);
    case HAL_S32: return pyb::int_(v.s);
    case HAL_U32: return pyb::int_(v.u);
    case HAL_S64: return pyb::int_(v.ls);
    case HAL_U64: return pyb::int_(v.lu);
    default: return pyb::none();
    }
}

hal_value load_value(hal_type_t type, const volatile void* addr)
{
    hal_value v{};
    switch (type) {
    case HAL_BIT: v.b = *static_cast<const volatile bool*>(addr); break;
    case HAL_FLOAT: v.f = *static_cast<const volatile double*>(addr); break;
    case HAL_S32: v.s = *static_cast<const volatile int32_t*>(addr); break;
    case HAL_U32: v.u = *static_cast<const volatile uint32_t*>(addr); break;
    case HAL_S64:
        v.ls = __atomic_load_n(static_cast<const volatile long long*>(addr), __ATOMIC_RELAXED);
        break;
    case HAL_U64:
        v.lu = __atomic_load_n(static_cast<const volatile unsigned long long*>(addr), __ATOMIC_RELAXED);
        break;
    default: break;
    }
    return v;
}

void store_value(hal_type_t type, volatile void* addr, const hal_value& v)
{
    switch (type) {
    case HAL_BIT: *static_cast<volatile bool*>(addr) = v.b; break;
    case HAL_FLOAT: *static_cast<volatile double*>(addr) = v.f; break;
    case HAL_S32: *static_cast<volatile int32_t*>(addr) = v.s; break;
    case HAL_U32: *static_cast<volatile uint32_t*>(addr) = v.u; break;
    case HAL_S64:
        __atomic_store_n(static_cast<volatile long long*>(addr), v.ls, __ATOMIC_RELAXED);
        break;
    case HAL_U64:
        __atomic_store_n(static_cast<volatile unsigned long long*>(addr), v.lu, __ATOMIC_RELAXED);
        break;
    default: break;
    }
}

}  // namespace hal::py
