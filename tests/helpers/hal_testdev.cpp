// SPDX-License-Identifier: GPL-2.0-or-later
// hal_testdev - virtual input devices for the hal_input and shuttlexpress tests, made
// with the kernel's uinput and uhid (in the kernel-test VM, or on a host where
// /dev/uinput and /dev/uhid are writable):
//
//   hal_testdev uinput NAME   a jog pendant: buttons BTN_1..BTN_3 (codes 257..259),
//                             ABS_X (-512..511), ABS_Y (0..1023), REL_DIAL, LED_MISC.
//                             Nothing a desktop takes for a keyboard or mouse.
//   hal_testdev uhid          a ShuttleXpress (USB 0b33:0020) whose 5-byte input
//                             report is laid out as shuttlexpress(1) reads it
//   hal_testdev read DEVNODE  opens an evdev node as a second reader, prints "reading",
//                             counts the key/abs/rel events it gets until a line or
//                             the end comes on stdin, then prints "events N"
//
// The device commands come one per line on stdin; every line printed is flushed:
//   uinput:  key|abs|rel CODE VALUE (an event and SYN_REPORT), destroy, create, quit;
//            prints "ready /dev/input/eventN" after create, "gone" after destroy and
//            "led CODE VALUE" for every LED event a reader writes to the device
//   uhid:    report B0 B1 B2 B3 B4 (bytes, decimal or 0x..), destroy, create, quit;
//            prints "ready /dev/hidrawN" and "gone"
// Any bad line gets "error: ..." and exit 1: the test must not go on silently.
#include <dirent.h>
#include <fcntl.h>
#include <linux/input.h>
#include <linux/uhid.h>
#include <linux/uinput.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <string>

namespace {

[[noreturn]] void fail(const std::string& what)
{
    std::printf("error: %s\n", what.c_str());
    std::fflush(stdout);
    std::exit(1);
}

void say(const std::string& line)
{
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
}

long long now_ms()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1000LL + ts.tv_nsec / 1000000;
}

void xioctl(int fd, unsigned long req, unsigned long arg, const char* what)
{
    if (ioctl(fd, req, arg) < 0)
        fail(std::string(what) + ": " + std::strerror(errno));
}

// The first entry of DIR whose name starts with PREFIX ("event", "hidraw"), or nullopt.
std::optional<std::string> entry_with_prefix(const std::string& dir, const char* prefix)
{
    DIR* d = opendir(dir.c_str());
    if (!d)
        return std::nullopt;
    std::optional<std::string> found;
    while (dirent* e = readdir(d))
        if (std::strncmp(e->d_name, prefix, std::strlen(prefix)) == 0) {
            found = e->d_name;
            break;
        }
    closedir(d);
    return found;
}

// Waits up to 5 s for the device node NODE to exist (devtmpfs makes it).
void wait_node(const std::string& node)
{
    for (long long end = now_ms() + 5000; access(node.c_str(), F_OK) != 0; usleep(10000))
        if (now_ms() > end)
            fail(node + " did not appear");
}

// The command lines on stdin, read with read(2) as poll(2) reports them (stdio would
// buffer lines that poll then no longer sees).
class LineReader {
public:
    // Reads what is there; false at end of input.
    bool fill()
    {
        char buf[512];
        ssize_t n = read(STDIN_FILENO, buf, sizeof(buf));
        if (n < 0)
            return errno == EINTR || errno == EAGAIN;
        pending_.append(buf, static_cast<size_t>(n));
        return n > 0;
    }
    // The next complete line as words; false when none is complete.
    bool next(std::istringstream& words)
    {
        size_t nl = pending_.find('\n');
        if (nl == std::string::npos)
            return false;
        words.clear();
        words.str(pending_.substr(0, nl));
        pending_.erase(0, nl + 1);
        return true;
    }

private:
    std::string pending_;
};

long number(std::istringstream& words, const std::string& cmd)
{
    std::string w;
    if (!(words >> w))
        fail("'" + cmd + "': a number is missing");
    char* end = nullptr;
    long v = std::strtol(w.c_str(), &end, 0);
    if (*end)
        fail("'" + cmd + "': '" + w + "' is not a number");
    return v;
}

// The loop both virtual devices run: command lines from stdin (command returns false
// for "quit"), and the device's own events (LEDs, open/close) drained as they come.
// fd is -1 while the test has the device destroyed.
template <typename Drain, typename Command>
void serve_device(int& fd, Drain drain, Command command)
{
    LineReader input;
    std::istringstream words;
    for (bool running = true; running;) {
        pollfd p[2] = {{STDIN_FILENO, POLLIN, 0}, {fd, POLLIN, 0}};
        if (poll(p, fd >= 0 ? 2 : 1, -1) < 0)
            continue;
        if (fd >= 0 && (p[1].revents & POLLIN))
            drain(fd);
        if (!(p[0].revents & (POLLIN | POLLHUP)))
            continue;
        running = input.fill();
        while (running && input.next(words))
            running = command(fd, words);
    }
}

// ---- uinput ------------------------------------------------------------------------

int uinput_create(const std::string& name)
{
    int fd = open("/dev/uinput", O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        fail(std::string("cannot open /dev/uinput: ") + std::strerror(errno));
    xioctl(fd, UI_SET_EVBIT, EV_KEY, "UI_SET_EVBIT EV_KEY");
    for (int b = BTN_1; b <= BTN_3; b++)
        xioctl(fd, UI_SET_KEYBIT, b, "UI_SET_KEYBIT");
    xioctl(fd, UI_SET_EVBIT, EV_REL, "UI_SET_EVBIT EV_REL");
    xioctl(fd, UI_SET_RELBIT, REL_DIAL, "UI_SET_RELBIT");
    xioctl(fd, UI_SET_EVBIT, EV_LED, "UI_SET_EVBIT EV_LED");
    xioctl(fd, UI_SET_LEDBIT, LED_MISC, "UI_SET_LEDBIT");
    xioctl(fd, UI_SET_EVBIT, EV_ABS, "UI_SET_EVBIT EV_ABS");
    struct { int code, min, max; } axes[] = {{ABS_X, -512, 511}, {ABS_Y, 0, 1023}};
    for (auto& a : axes) {
        xioctl(fd, UI_SET_ABSBIT, static_cast<unsigned long>(a.code), "UI_SET_ABSBIT");
        uinput_abs_setup s{};
        s.code = static_cast<__u16>(a.code);
        s.absinfo.minimum = a.min;
        s.absinfo.maximum = a.max;
        if (ioctl(fd, UI_ABS_SETUP, &s) < 0)
            fail(std::string("UI_ABS_SETUP: ") + std::strerror(errno));
    }
    uinput_setup setup{};
    setup.id.bustype = BUS_VIRTUAL;
    setup.id.vendor = 0x1d6b;          // the Linux Foundation's id, as virtual devices use
    setup.id.product = 0x4851;
    setup.id.version = 1;
    std::snprintf(setup.name, sizeof(setup.name), "%s", name.c_str());
    if (ioctl(fd, UI_DEV_SETUP, &setup) < 0)
        fail(std::string("UI_DEV_SETUP: ") + std::strerror(errno));
    xioctl(fd, UI_DEV_CREATE, 0, "UI_DEV_CREATE");
    char sysname[64] = {};
    if (ioctl(fd, UI_GET_SYSNAME(sizeof(sysname)), sysname) < 0)
        fail(std::string("UI_GET_SYSNAME: ") + std::strerror(errno));
    std::string dir = std::string("/sys/class/input/") + sysname;
    std::optional<std::string> ev;
    for (long long end = now_ms() + 5000; !(ev = entry_with_prefix(dir, "event")); usleep(10000))
        if (now_ms() > end)
            fail(dir + " has no event node (is evdev loaded?)");
    std::string node = "/dev/input/" + *ev;
    wait_node(node);
    say("ready " + node);
    return fd;
}

void uinput_emit(int fd, int type, int code, int value)
{
    input_event ev[2] = {};
    ev[0].type = static_cast<__u16>(type);
    ev[0].code = static_cast<__u16>(code);
    ev[0].value = value;
    ev[1].type = EV_SYN;
    ev[1].code = SYN_REPORT;
    if (write(fd, ev, sizeof(ev)) != static_cast<ssize_t>(sizeof(ev)))
        fail(std::string("writing to /dev/uinput: ") + std::strerror(errno));
}

// LED changes written by the device's readers arrive on the uinput fd as EV_LED.
void uinput_drain(int fd)
{
    input_event ev{};
    while (read(fd, &ev, sizeof(ev)) == static_cast<ssize_t>(sizeof(ev)))
        if (ev.type == EV_LED)
            say("led " + std::to_string(ev.code) + " " + std::to_string(ev.value));
}

// One command line; false for "quit". fd is -1 while the device is destroyed.
bool uinput_command(int& fd, const std::string& name, std::istringstream& words)
{
    std::string cmd;
    if (!(words >> cmd))
        return true;
    if (cmd == "quit")
        return false;
    if (cmd == "create") {
        if (fd < 0)
            fd = uinput_create(name);
    } else if (cmd == "destroy") {
        if (fd >= 0) {
            ioctl(fd, UI_DEV_DESTROY);
            close(fd);
            fd = -1;
        }
        say("gone");
    } else if (cmd == "key" || cmd == "abs" || cmd == "rel") {
        if (fd < 0)
            fail("'" + cmd + "': the device is destroyed");
        int code = static_cast<int>(number(words, cmd));
        int value = static_cast<int>(number(words, cmd));
        uinput_emit(fd, cmd == "key" ? EV_KEY : cmd == "abs" ? EV_ABS : EV_REL, code, value);
    } else {
        fail("unknown command '" + cmd + "'");
    }
    return true;
}

int run_uinput(const std::string& name)
{
    int fd = uinput_create(name);
    serve_device(fd, uinput_drain,
                 [&](int& f, std::istringstream& words) { return uinput_command(f, name, words); });
    if (fd >= 0) {
        ioctl(fd, UI_DEV_DESTROY);
        close(fd);
    }
    return 0;
}

// ---- uhid: the ShuttleXpress ------------------------------------------------------

// Input report (no report id), as user/shuttlexpress/shuttle_report.hpp decodes it:
// byte 0 spring wheel -7..7, byte 1 jog counter, byte 2 unused, byte 3 bits 4..7
// buttons 1..4, byte 4 bit 0 button 5, the rest padding.
constexpr unsigned char shuttle_descriptor[] = {
    0x05, 0x0c,        // Usage Page (Consumer)
    0x09, 0x01,        // Usage (Consumer Control)
    0xa1, 0x01,        // Collection (Application)
    0x05, 0x01,        //   Usage Page (Generic Desktop)
    0x09, 0x37,        //   Usage (Dial): the spring-loaded shuttle ring
    0x15, 0xf9,        //   Logical Minimum (-7)
    0x25, 0x07,        //   Logical Maximum (7)
    0x75, 0x08,        //   Report Size (8)
    0x95, 0x01,        //   Report Count (1)
    0x81, 0x06,        //   Input (Data, Var, Rel)
    0x09, 0x38,        //   Usage (Wheel): the jog wheel's counter
    0x15, 0x00,        //   Logical Minimum (0)
    0x26, 0xff, 0x00,  //   Logical Maximum (255)
    0x81, 0x02,        //   Input (Data, Var, Abs)
    0x75, 0x0c,        //   Report Size (12): byte 2 and the low half of byte 3
    0x81, 0x01,        //   Input (Const)
    0x05, 0x09,        //   Usage Page (Button)
    0x19, 0x01,        //   Usage Minimum (1)
    0x29, 0x05,        //   Usage Maximum (5)
    0x15, 0x00,        //   Logical Minimum (0)
    0x25, 0x01,        //   Logical Maximum (1)
    0x75, 0x01,        //   Report Size (1)
    0x95, 0x05,        //   Report Count (5)
    0x81, 0x02,        //   Input (Data, Var, Abs)
    0x75, 0x07,        //   Report Size (7)
    0x95, 0x01,        //   Report Count (1)
    0x81, 0x01,        //   Input (Const)
    0xc0,              // End Collection
};
constexpr const char* shuttle_name = "Contour Design ShuttleXpress (hal_testdev)";

void uhid_write(int fd, const uhid_event& ev)
{
    if (write(fd, &ev, sizeof(ev)) != static_cast<ssize_t>(sizeof(ev)))
        fail(std::string("writing to /dev/uhid: ") + std::strerror(errno));
}

// The hidraw node of our device: the kernel adds it asynchronously after UHID_CREATE2.
std::string uhid_find_hidraw()
{
    for (long long end = now_ms() + 5000; now_ms() < end; usleep(20000)) {
        DIR* d = opendir("/sys/class/hidraw");
        if (!d)
            continue;
        std::string found;
        while (dirent* e = readdir(d)) {
            if (std::strncmp(e->d_name, "hidraw", 6) != 0)
                continue;
            std::string uevent = std::string("/sys/class/hidraw/") + e->d_name + "/device/uevent";
            FILE* f = std::fopen(uevent.c_str(), "r");
            if (!f)
                continue;
            char line[256];
            while (std::fgets(line, sizeof(line), f))
                if (std::strncmp(line, "HID_NAME=", 9) == 0 && std::strstr(line, shuttle_name))
                    found = e->d_name;
            std::fclose(f);
        }
        closedir(d);
        if (!found.empty()) {
            std::string node = "/dev/" + found;
            wait_node(node);
            return node;
        }
    }
    fail("no hidraw node for the uhid device (are hid, uhid and hid-generic loaded?)");
}

int uhid_create()
{
    int fd = open("/dev/uhid", O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        fail(std::string("cannot open /dev/uhid: ") + std::strerror(errno));
    uhid_event ev{};
    ev.type = UHID_CREATE2;
    std::snprintf(reinterpret_cast<char*>(ev.u.create2.name), sizeof(ev.u.create2.name), "%s", shuttle_name);
    std::snprintf(reinterpret_cast<char*>(ev.u.create2.phys), sizeof(ev.u.create2.phys), "hal_testdev/uhid");
    std::memcpy(ev.u.create2.rd_data, shuttle_descriptor, sizeof(shuttle_descriptor));
    ev.u.create2.rd_size = sizeof(shuttle_descriptor);
    ev.u.create2.bus = BUS_USB;
    ev.u.create2.vendor = 0x0b33;
    ev.u.create2.product = 0x0020;
    ev.u.create2.version = 0x0100;
    uhid_write(fd, ev);
    say("ready " + uhid_find_hidraw());
    return fd;
}

// Requests from the kernel: start/stop/open/close need nothing; a GET/SET_REPORT
// must be answered or the asker waits for its timeout.
void uhid_drain(int fd)
{
    uhid_event ev{};
    while (read(fd, &ev, sizeof(ev)) > 0) {
        uhid_event reply{};
        if (ev.type == UHID_GET_REPORT) {
            reply.type = UHID_GET_REPORT_REPLY;
            reply.u.get_report_reply.id = ev.u.get_report.id;
            reply.u.get_report_reply.err = EIO;
            uhid_write(fd, reply);
        } else if (ev.type == UHID_SET_REPORT) {
            reply.type = UHID_SET_REPORT_REPLY;
            reply.u.set_report_reply.id = ev.u.set_report.id;
            reply.u.set_report_reply.err = EIO;
            uhid_write(fd, reply);
        }
    }
}

// One command line; false for "quit". fd is -1 while the device is destroyed.
bool uhid_command(int& fd, std::istringstream& words)
{
    std::string cmd;
    if (!(words >> cmd))
        return true;
    if (cmd == "quit")
        return false;
    if (cmd == "create") {
        if (fd < 0)
            fd = uhid_create();
    } else if (cmd == "destroy") {
        if (fd >= 0) {
            uhid_event ev{};
            ev.type = UHID_DESTROY;
            uhid_write(fd, ev);
            close(fd);
            fd = -1;
        }
        say("gone");
    } else if (cmd == "report") {
        if (fd < 0)
            fail("'report': the device is destroyed");
        uhid_event ev{};
        ev.type = UHID_INPUT2;
        ev.u.input2.size = 5;
        for (int i = 0; i < 5; i++)
            ev.u.input2.data[i] = static_cast<__u8>(number(words, cmd));
        uhid_write(fd, ev);
    } else {
        fail("unknown command '" + cmd + "'");
    }
    return true;
}

int run_uhid()
{
    int fd = uhid_create();
    serve_device(fd, uhid_drain, uhid_command);
    if (fd >= 0)
        close(fd);            // closing /dev/uhid destroys the device
    return 0;
}

// ---- a second reader ----------------------------------------------------------------

// Events are delivered to every reader of a device at once: when the test has seen
// hal_input act on them, this reader has them queued too (unless the device is grabbed).
int run_read(const char* node)
{
    int fd = open(node, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        fail(std::string("cannot open ") + node + ": " + std::strerror(errno));
    say("reading");
    int count = 0;
    for (bool done = false; !done;) {
        pollfd p[2] = {{fd, POLLIN, 0}, {STDIN_FILENO, POLLIN, 0}};
        if (poll(p, 2, -1) < 0)
            continue;
        done = p[1].revents & (POLLIN | POLLHUP);
        input_event ev{};
        while (read(fd, &ev, sizeof(ev)) == static_cast<ssize_t>(sizeof(ev)))
            if (ev.type == EV_KEY || ev.type == EV_ABS || ev.type == EV_REL)
                count++;
    }
    close(fd);
    say("events " + std::to_string(count));
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "uinput" && argc == 3)
        return run_uinput(argv[2]);
    if (mode == "uhid" && argc == 2)
        return run_uhid();
    if (mode == "read" && argc == 3)
        return run_read(argv[2]);
    std::fprintf(stderr, "usage: hal_testdev uinput NAME | uhid | read DEVNODE\n");
    return 1;
}
