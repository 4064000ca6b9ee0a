// SPDX-License-Identifier: GPL-2.0-or-later
// input_device.cpp - InputDevice: evdev I/O and pins; see input_device.hpp.
#include "input_device.hpp"

#include <fcntl.h>
#include <linux/input.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "input_axes.hpp"
#include "input_udev.hpp"

namespace hal::input {

namespace {

struct EventName { int type; int code; const char* name; };
constexpr EventName event_names[] = {
#include "event_names.inc"
};

// "key-a", "btn-left", "abs-x", ... or "key-0x2f0" for a code without a name.
std::string code_name(int type, int code)
{
    for (const EventName& e : event_names)
        if (e.type == type && e.code == code)
            return e.name;
    const char* prefix = type == EV_KEY ? "key" : type == EV_ABS ? "abs" : type == EV_REL ? "rel" : "led";
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%s-0x%03x", prefix, code);
    return buf;
}

bool test_bit(const unsigned long* bits, int n)
{
    return (bits[n / (8 * sizeof(long))] >> (n % (8 * sizeof(long)))) & 1;
}

constexpr int nlongs(int bits) { return (bits + 8 * static_cast<int>(sizeof(long)) - 1) / (8 * static_cast<int>(sizeof(long))); }

long long now_ms()
{
    using namespace std::chrono;
    return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
}

template <typename T>
T* hal_new()
{
    auto* p = static_cast<T*>(hal_malloc(sizeof(T)));
    if (p)
        std::memset(static_cast<void*>(p), 0, sizeof(T));
    return p;
}

}  // namespace

InputDevice::~InputDevice()
{
    if (fd_ >= 0)
        close(fd_);
}

int InputDevice::open_device(const DeviceInfo& d)
{
    int fd = open(d.devnode.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        int e = errno;
        std::fprintf(stderr, "hal_input: cannot open %s ('%s') for reading and writing: %s%s\n", d.devnode.c_str(),
                     d.name.c_str(), std::strerror(e),
                     e == EACCES ? " (see PERMISSIONS AND UDEV in hal_input(1))" : "");
        return -e;
    }
    if (spec_.exclusive && ioctl(fd, EVIOCGRAB, 1) < 0) {
        int e = errno;
        std::fprintf(stderr, "hal_input: cannot get exclusive access to %s ('%s'): %s\n", d.devnode.c_str(),
                     d.name.c_str(), std::strerror(e));
        close(fd);
        return -e;
    }
    fd_ = fd;
    devnode_ = d.devnode;
    return 0;
}

int InputDevice::open_and_export(const DeviceInfo& d, int id)
{
    if (int rc = open_device(d); rc < 0)
        return rc;
    unsigned long types[nlongs(EV_CNT)] = {}, keys[nlongs(KEY_CNT)] = {}, abs[nlongs(ABS_CNT)] = {},
                  rel[nlongs(REL_CNT)] = {}, leds[nlongs(LED_CNT)] = {};
    ioctl(fd_, EVIOCGBIT(0, sizeof(types)), types);
    if (test_bit(types, EV_KEY))
        ioctl(fd_, EVIOCGBIT(EV_KEY, sizeof(keys)), keys);
    if (test_bit(types, EV_ABS))
        ioctl(fd_, EVIOCGBIT(EV_ABS, sizeof(abs)), abs);
    if (test_bit(types, EV_REL))
        ioctl(fd_, EVIOCGBIT(EV_REL, sizeof(rel)), rel);
    if (test_bit(types, EV_LED))
        ioctl(fd_, EVIOCGBIT(EV_LED, sizeof(leds)), leds);
    int rc = 0;
    auto name = [&](int type, int code) { return "input." + std::to_string(number_) + "." + code_name(type, code); };
    for (int c = 0; !rc && spec_.features.keys && c < KEY_CNT; c++) {
        if (!test_bit(keys, c))
            continue;
        auto* k = hal_new<KeyPins>();
        if (!k)
            return -ENOMEM;
        k->code = c;
        std::string n = name(EV_KEY, c);
        rc = hal_pin_bit_newf(HAL_OUT, &k->on, id, "%s", n.c_str());
        if (!rc)
            rc = hal_pin_bit_newf(HAL_OUT, &k->off, id, "%s-not", n.c_str());
        if (!rc)
            *k->off = true;
        keys_.push_back(k);
    }
    for (int c = 0; !rc && spec_.features.abs && c < ABS_CNT; c++) {
        if (!test_bit(abs, c))
            continue;
        auto* a = hal_new<AbsPins>();
        if (!a)
            return -ENOMEM;
        a->code = c;
        std::string n = name(EV_ABS, c);
        const char* s = n.c_str();
        rc = hal_pin_s32_newf(HAL_OUT, &a->counts, id, "%s-counts", s);
        if (!rc) rc = hal_pin_float_newf(HAL_OUT, &a->position, id, "%s-position", s);
        if (!rc) rc = hal_param_float_newf(HAL_RW, &a->scale, id, "%s-scale", s);
        if (!rc) rc = hal_param_float_newf(HAL_RW, &a->offset, id, "%s-offset", s);
        if (!rc) rc = hal_param_s32_newf(HAL_RW, &a->fuzz, id, "%s-fuzz", s);
        if (!rc) rc = hal_param_s32_newf(HAL_RW, &a->flat, id, "%s-flat", s);
        if (!rc) rc = hal_param_s32_newf(HAL_RO, &a->min, id, "%s-min", s);
        if (!rc) rc = hal_param_s32_newf(HAL_RO, &a->max, id, "%s-max", s);
        input_absinfo info = {};
        ioctl(fd_, EVIOCGABS(c), &info);
        AbsDefaults def = abs_defaults(info.minimum, info.maximum);
        a->scale = def.scale;
        a->offset = def.offset;
        a->fuzz = info.fuzz;
        a->flat = info.flat;
        a->min = info.minimum;
        a->max = info.maximum;
        abs_.push_back(a);
    }
    for (int c = 0; !rc && spec_.features.rel && c < REL_CNT; c++) {
        if (!test_bit(rel, c))
            continue;
        auto* r = hal_new<RelPins>();
        if (!r)
            return -ENOMEM;
        r->code = c;
        std::string n = name(EV_REL, c);
        const char* s = n.c_str();
        rc = hal_pin_s32_newf(HAL_OUT, &r->counts, id, "%s-counts", s);
        if (!rc) rc = hal_pin_float_newf(HAL_OUT, &r->position, id, "%s-position", s);
        if (!rc) rc = hal_pin_bit_newf(HAL_IN, &r->reset, id, "%s-reset", s);
        if (!rc) rc = hal_param_float_newf(HAL_RW, &r->scale, id, "%s-scale", s);
        if (!rc) rc = hal_param_s32_newf(HAL_RW, &r->absolute, id, "%s-absolute", s);
        if (!rc) rc = hal_param_s32_newf(HAL_RW, &r->precision, id, "%s-precision", s);
        if (!rc) rc = hal_param_s32_newf(HAL_RW, &r->last, id, "%s-last", s);
        r->scale = 1;
        r->precision = 32;
        rel_.push_back(r);
    }
    for (int c = 0; !rc && spec_.features.leds && c < LED_CNT; c++) {
        if (!test_bit(leds, c))
            continue;
        auto* l = hal_new<LedPins>();
        if (!l)
            return -ENOMEM;
        l->code = c;
        l->sent = -1;
        std::string n = name(EV_LED, c);
        rc = hal_pin_bit_newf(HAL_IN, &l->in, id, "%s", n.c_str());
        if (!rc)
            rc = hal_param_bit_newf(HAL_RW, &l->invert, id, "%s-invert", n.c_str());
        leds_.push_back(l);
    }
    if (rc)
        return rc;
    read_initial_state();
    return 0;
}

// The state before the first event (hal_input(1) BUGS: no longer FALSE/0 until then).
void InputDevice::read_initial_state()
{
    unsigned long keys[nlongs(KEY_CNT)] = {};
    if (!keys_.empty() && ioctl(fd_, EVIOCGKEY(sizeof(keys)), keys) >= 0)
        for (KeyPins* k : keys_)
            handle(EV_KEY, k->code, test_bit(keys, k->code) ? 1 : 0);
    for (AbsPins* a : abs_) {
        input_absinfo info = {};
        if (ioctl(fd_, EVIOCGABS(a->code), &info) >= 0)
            handle(EV_ABS, a->code, info.value);
    }
}

void InputDevice::handle(int type, int code, int value)
{
    if (type == EV_KEY) {
        for (KeyPins* k : keys_)
            if (k->code == code) {
                *k->on = value != 0;      // 1 press, 2 autorepeat, 0 release
                *k->off = value == 0;
            }
    } else if (type == EV_ABS) {
        for (AbsPins* a : abs_)
            if (a->code == code) {
                *a->counts = abs_counts(*a->counts, value, a->offset, a->fuzz, a->flat);
                *a->position = abs_position(*a->counts, a->offset, a->scale);
            }
    } else if (type == EV_REL) {
        for (RelPins* r : rel_)
            if (r->code == code) {
                RelState st{*r->counts, r->last};
                rel_event(st, value, r->precision, r->absolute != 0);
                if (!*r->reset)
                    *r->counts = st.counts;
                r->last = st.last;
                *r->position = rel_position(*r->counts, r->scale);
            }
    }
}

void InputDevice::gone(const char* why)
{
    std::fprintf(stderr, "hal_input: input.%d: %s ('%s') %s; waiting for it to come back\n", number_,
                 devnode_.c_str(), spec_.text.c_str(), why);
    close(fd_);
    fd_ = -1;
    for (KeyPins* k : keys_) {            // nobody holds a key of an unplugged device
        *k->on = false;
        *k->off = true;
    }
    for (LedPins* l : leds_)
        l->sent = -1;
    next_scan_ms_ = now_ms() + 1000;
}

void InputDevice::update()
{
    for (RelPins* r : rel_)               // counts stay 0 while reset is held
        if (*r->reset) {
            *r->counts = 0;
            *r->position = 0;
        }
    if (fd_ < 0)
        return;
    input_event ev[64];
    for (;;) {
        ssize_t n = read(fd_, ev, sizeof(ev));
        if (n < 0) {
            if (errno == EAGAIN || errno == EINTR)
                break;
            gone(errno == ENODEV ? "was unplugged" : std::strerror(errno));
            return;
        }
        if (n == 0)
            break;
        for (size_t i = 0; i < static_cast<size_t>(n) / sizeof(input_event); i++)
            handle(ev[i].type, ev[i].code, ev[i].value);
    }
    for (LedPins* l : leds_) {
        int want = (*l->in != l->invert) ? 1 : 0;
        if (want == l->sent)
            continue;
        input_event out[2] = {};
        out[0].type = EV_LED;
        out[0].code = static_cast<__u16>(l->code);
        out[0].value = want;
        out[1].type = EV_SYN;
        out[1].code = SYN_REPORT;
        if (write(fd_, out, sizeof(out)) == static_cast<ssize_t>(sizeof(out)))
            l->sent = want;
    }
}

void InputDevice::try_reopen()
{
    if (fd_ >= 0 || now_ms() < next_scan_ms_)
        return;
    next_scan_ms_ = now_ms() + 1000;
    auto d = select_device(spec_, scan_input_devices());
    if (!d || open_device(*d) < 0)
        return;
    std::fprintf(stderr, "hal_input: input.%d: '%s' is back as %s\n", number_, spec_.text.c_str(), d->devnode.c_str());
    read_initial_state();
}

}  // namespace hal::input
