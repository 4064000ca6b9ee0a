// SPDX-License-Identifier: GPL-2.0-or-later
// io_estop.hpp - which of iocontrol's estop reports task believes (docs/task.md
// "States and modes").
//
// io reports `IOSTAT estop=E ... ack=N`: E is the estop input as io read it, N the
// last of task's commands whose outputs io had written before reading it. Reports
// cross commands on the way: after task sends ESTOP_ON and then ESTOP_OFF (an estop
// and a quick reset, or a restarted task meeting an io that still has the machine
// enabled), io may still send estop=0 from before the ESTOP_ON, and then estop=1 from
// before the ESTOP_OFF took effect. Believing the first ends the reset too early,
// believing the second after that looks like the external chain opening. So a report
// counts only when it follows the last ESTOP_ON/ESTOP_OFF sent (ack >= its serial);
// an older one leaves the estop state as it was. ESTOP_ON latches: task is in estop
// from the moment it sends it until an ESTOP_OFF's report says otherwise, as
// EMC2's iocontrol latched it (an emc-enable-in held TRUE does not undo an estop).
#pragma once

#include <map>
#include <string>

namespace hal::task {

class IoEstop {
public:
    void connected();                 // a new io link: estop until io reports after task's commands
    void disconnected();
    void sent(long serial, bool on);  // ESTOP_ON (on) or ESTOP_OFF went to io with this serial
    void report(bool estop, long ack);
    // estop as task takes it: no io, or io's last report that counts said estop
    bool estop() const { return !connected_ || estop_; }
    // io has reported after the last ESTOP_ON/ESTOP_OFF (an ESTOP_RESET is done when
    // this holds and estop() is false)
    bool settled() const { return connected_ && ack_ >= sync_; }

private:
    bool connected_ = false;
    bool estop_ = true;
    long sync_ = 0;   // serial of the last ESTOP_ON/ESTOP_OFF sent
    long ack_ = 0;    // ack of the last report
    bool on_ = false; // the last of them was ESTOP_ON
};

// The key=value words of an IOSTAT line's body (non-numeric values left out).
std::map<std::string, long> parse_iostat(const std::string& body);

}  // namespace hal::task
