// SPDX-License-Identifier: GPL-2.0-or-later
// bus_machine.cpp - a session's connection to task over the machine bus (machine.hpp).
#include <algorithm>
#include <cerrno>
#include <chrono>

#include "machine.hpp"

namespace hal::emcrsh {

using namespace std::chrono;

static milliseconds limit(double timeout_s)
{
    // no limit: a year is forever for an operator waiting on a command
    if (timeout_s <= 0)
        return hours(24 * 365);
    return milliseconds(static_cast<long>(timeout_s * 1000 + 0.5));
}

Result<bus::Client*> BusMachine::client()
{
    if (!c_) {
        auto c = bus::Client::connect(path_, "client", seconds(2));
        if (!c)
            return c.error();
        c_ = std::move(*c);
        last_ = 0;
        unwaited_.clear();
    }
    return c_.get();
}

Result<void> BusMachine::lost(const Error& e)
{
    // a broken connection (task restarted) is reopened by the next request
    if (e.code == -EPIPE || e.message.find("closed") != std::string::npos) {
        for (auto& m : c_->take_messages())
            errors_.push_back(m);
        c_.reset();
    }
    return e;
}

void BusMachine::reap()
{
    // commands sent without waiting to the end: collect their outcome (an error
    // becomes an ERROR message for GET ERROR) and forget them
    std::vector<long> keep;
    for (long s : unwaited_) {
        if (!c_->received(s)) {
            keep.push_back(s);
            continue;
        }
        auto r = c_->wait_done(s, milliseconds(0));
        if (r)
            continue;
        if (r.error().code == -ETIMEDOUT)
            keep.push_back(s);   // received, still running
        else
            errors_.push_back({"ERROR", r.error().message});
    }
    unwaited_ = std::move(keep);
}

Result<void> BusMachine::wait_for(long serial, Wait wait, double timeout_s)
{
    if (wait == Wait::NONE)
        return ok();
    auto deadline = steady_clock::now() + limit(timeout_s);
    if (wait == Wait::DONE) {
        auto r = c_->wait_done(serial, limit(timeout_s));
        std::erase(unwaited_, serial);
        return r ? r : lost(r.error());
    }
    while (!c_->received(serial)) {
        auto left = duration_cast<milliseconds>(deadline - steady_clock::now());
        if (left.count() <= 0)
            return Error{-ETIMEDOUT, "not received within " + std::to_string(timeout_s) + " s"};
        if (auto r = c_->pump(std::min(left, milliseconds(100))); !r)
            return lost(r.error());
    }
    // received, or refused at once (ERROR without RECEIVED): that one counts
    auto r = c_->wait_done(serial, milliseconds(0));
    if (!r && r.error().code == -ETIMEDOUT)
        return ok();   // accepted, still running
    std::erase(unwaited_, serial);
    return r;
}

Result<void> BusMachine::command(const std::string& line, Wait wait, double timeout_s)
{
    auto c = client();
    if (!c)
        return c.error();
    reap();
    auto serial = (*c)->send(line);
    if (!serial)
        return lost(serial.error());
    last_ = *serial;
    unwaited_.push_back(last_);
    return wait_for(last_, wait, timeout_s);
}

Result<void> BusMachine::wait_last(Wait wait, double timeout_s)
{
    if (!c_ || last_ == 0)
        return ok();   // nothing sent: nothing to wait for
    if (std::find(unwaited_.begin(), unwaited_.end(), last_) == unwaited_.end())
        return ok();   // already waited to its end
    return wait_for(last_, wait, timeout_s);
}

Result<bus::Status> BusMachine::status()
{
    auto c = client();
    if (!c)
        return c.error();
    auto st = (*c)->status(seconds(5));
    if (!st) {
        auto e = lost(st.error());
        return e.error();
    }
    return st;
}

void BusMachine::pump()
{
    if (c_)
        if (auto r = c_->pump(milliseconds(0)); !r)
            (void)lost(r.error());
}

std::vector<bus::Message> BusMachine::take_messages()
{
    std::vector<bus::Message> out;
    if (c_) {
        reap();
        for (auto& m : c_->take_messages())
            out.push_back(m);
    }
    for (auto& m : errors_)
        out.push_back(m);
    errors_.clear();
    return out;
}

}  // namespace hal::emcrsh
