// SPDX-License-Identifier: GPL-2.0-or-later
// task.cpp - task's loop: motion link, state, the work queue, read-ahead (see task.hpp).
#include "task.hpp"

#include "position_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sys/wait.h>
#include <unistd.h>

namespace hal::task {

using namespace std::chrono;

// Moves kept in motion's queue at most (motmod's planner holds 2000): enough to keep
// the planner's look-ahead fed, with room left for what task sends meanwhile.
static constexpr int MOTION_QUEUE_LIMIT = 1000;
// Interpreter blocks read per cycle at most, so a long program cannot starve the bus.
static constexpr int READ_AHEAD_PER_CYCLE = 500;

Task::Task(TaskConfig cfg, rs274::Config icfg, std::unique_ptr<MotionClient> motion,
           std::unique_ptr<bus::Server> server)
    : cfg_(std::move(cfg)), motion_(std::move(motion)), server_(std::move(server))
{
    canon_ = std::make_unique<TaskCanon>(cfg_, *this);
    interp_ = std::make_unique<rs274::Interp>(*canon_, std::move(icfg));
}

Task::~Task() = default;

bool Task::init(std::string& error)
{
    in_interp_ = true;
    bool ok = interp_->init();
    in_interp_ = false;
    if (!ok) {
        error = interp_->error().to_string();
        return false;
    }
    return true;
}

void Task::run(volatile std::sig_atomic_t* stop)
{
    while (!*stop)
        cycle(false);
    save_positions();
    if (!interp_->save_parameters())
        std::fprintf(stderr, "milltask: %s\n", interp_->error().to_string().c_str());
}

void Task::error_all(const std::string& text)
{
    last_error_ = text;
    server_->broadcast("ERROR", text);
}

motion_command Task::mcmd(int type) const
{
    motion_command c{};
    c.command = type;
    c.axis = -1;
    return c;
}

bool Task::send_motion(motion_command c, std::string* err)
{
    auto r = motion_->send(c, milliseconds(static_cast<long>(cfg_.comm_timeout * 1000)));
    busy_until_heartbeat_ = mst_.heartbeat + 2;
    if (!r) {
        std::string e = "motion: " + r.error().message;
        if (err)
            *err = e;
        else
            error_all(e);
        return false;
    }
    if (*r != MOTION_CMD_OK) {
        // motion queues the reason; it reaches the clients through take_motion_errors()
        std::string e = std::string("motion refused ") + (c.command > 0 ? "the command" : "") + " (" +
                        motion_cmd_status_name(*r) + ")";
        auto msgs = motion_->take_errors();
        if (!msgs.empty())
            e = msgs.back();
        for (const std::string& m : msgs)
            error_all(m);
        if (err)
            *err = e;
        return false;
    }
    return true;
}

void Task::read_motion()
{
    auto s = motion_->status(milliseconds(100));
    if (s)
        mst_ = *s;
}

void Task::take_motion_errors()
{
    unsigned lost = 0;
    for (const std::string& m : motion_->take_errors(&lost))
        error_all(m);
    if (lost)
        error_all("motion: " + std::to_string(lost) + " messages lost (queue full)");
}

bool Task::motion_idle() const
{
    // after a send, a status from before it may still show an empty queue
    if (static_cast<int32_t>(mst_.heartbeat - busy_until_heartbeat_) < 0)
        return false;
    return mst_.depth == 0 && (mst_.motionFlag & MOTION_FLAG_INPOS) != 0;
}

bool Task::all_homed() const
{
    return mst_.all_homed != 0;
}

// Motion takes the INI settings once its command handler runs (the launcher starts
// task before the threads).
void Task::configure_motion()
{
    if (motion_ready_)
        return;
    if (!have_first_heartbeat_) {
        first_heartbeat_ = mst_.heartbeat;
        have_first_heartbeat_ = true;
        return;
    }
    if (mst_.heartbeat == first_heartbeat_)
        return;
    auto cmds = motion_init_commands(cfg_);
    if (!cmds) {
        error_all(cmds.error().message);
        motion_ready_ = true;   // nothing else to send; the error stays reported
        return;
    }
    for (const motion_command& c : *cmds) {
        std::string err;
        if (!send_motion(c, &err))
            error_all("configuring motion from " + cfg_.ini_path + ": " + err);
    }
    motion_ready_ = true;
}

// ini.* pins changed (halcmd setp, a net): the configuration follows, motion gets the
// commands for the new values (inihal_items.cpp). Before motion took the start-up
// settings the pins wait: the start-up commands will carry the values then.
void Task::apply_inihal()
{
    if (!inihal_ || !motion_ready_)
        return;
    for (const motion_command& c : inihal_->poll(cfg_)) {
        std::string err;
        if (!send_motion(c, &err))
            error_all("inihal: " + err);
    }
}

// [TRAJ]POSITION_FILE at exit: where the joints are, for the next start
void Task::save_positions()
{
    if (cfg_.position_file.empty() || !motion_ready_)
        return;   // motion never took our settings: the old file stays true
    read_motion();
    std::vector<double> pos;
    for (int j = 0; j < cfg_.joints && j < MOTION_MAX_JOINTS; ++j)
        pos.push_back(mst_.joint[j].pos_fb);
    if (auto r = write_position_file(cfg_.position_file, pos); !r)
        std::fprintf(stderr, "milltask: %s\n", r.error().message.c_str());
}

void Task::cycle(bool nested)
{
    ++heartbeat_;
    int timeout_ms = cfg_.cycle_time > 0 ? static_cast<int>(cfg_.cycle_time * 1000) : 0;
    // a program that is moving wants its queue topped up sooner than an idle machine
    if ((reading_ || !canon_->queue().empty()) && timeout_ms > 10)
        timeout_ms = 10;
    server_->poll_once(timeout_ms, *this);
    read_motion();
    take_motion_errors();
    configure_motion();
    apply_inihal();
    update_state();
    if (motion_ready_) {
        ensure_motion_mode();
        execute_queue();
        if (!nested) {
            read_ahead();
            start_next_mdi();
        }
    }
    check_waiters();
}

void Task::update_state()
{
    bool io_estop = io_estop_.estop();
    TaskState now = determine_state(io_estop, motion_enabled());
    // the estop input going active (not its level: after ESTOP_RESET it takes an io
    // cycle and the external chain to clear)
    bool rising = io_estop && !last_io_estop_;
    last_io_estop_ = io_estop;
    if (rising && requested_state_ != TaskState::ESTOP) {
        // an external estop (emc-enable-in FALSE) or iocontrol gone: everything stops
        error_all(io_.connected ? "emergency stop: iocontrol.0.emc-enable-in is FALSE"
                                : "emergency stop: iocontrol is not connected");
        requested_state_ = TaskState::ESTOP;
        do_estop_actions();
    }
    if (state_ == TaskState::ON && now != TaskState::ON) {
        // leaving ON for any reason (a fault disabled motion): stop what runs
        if (requested_state_ == TaskState::ON) {
            abort_task("machine turned off (motion disabled)");
            requested_state_ = now;
        }
    }
    state_ = now;
    current_line_ = canon_->view().line;
    if (motion_enabled())
        motion_line_ = mst_.id;
    refresh_interp_state();
}

// The interpreter state for status and for the checks of the next command: also called
// right after a mode change's abort, so a RUN that follows MODE AUTO sees IDLE.
void Task::refresh_interp_state()
{
    if (paused_ || (step_mode_ && step_hold_ && canon_->queue().empty() && motion_idle()))
        interp_state_ = InterpState::PAUSED;
    else if (reading_)
        interp_state_ = InterpState::READING;
    else if (program_running_ || mdi_running_ || !canon_->queue().empty())
        interp_state_ = InterpState::WAITING;
    else
        interp_state_ = InterpState::IDLE;
}

void Task::ensure_motion_mode()
{
    if (!motion_enabled())
        return;
    for (int j = 0; j < mst_.num_joints; ++j)
        if (mst_.joint[j].homing)
            return;   // homing needs FREE and ends in TELEOP by itself
    int want = mode_ == TaskMode::MANUAL ? (teleop_wanted_ && all_homed() ? MOTION_TELEOP : MOTION_FREE)
                                         : MOTION_COORD;
    if (mst_.motion_state == want || !(mst_.motionFlag & MOTION_FLAG_INPOS) || mst_.jogging_active)
        return;
    auto now = Clock::now();
    if (now - last_mode_send_ < milliseconds(100))
        return;
    last_mode_send_ = now;
    int type = want == MOTION_COORD ? MOTCMD_COORD : want == MOTION_TELEOP ? MOTCMD_TELEOP : MOTCMD_FREE;
    std::string err;
    send_motion(mcmd(type), &err);   // refused (not homed, kinematics) -> stays; the reason is in motion's errors
}

long Task::io_send(const std::vector<std::string>& words)
{
    long n = ++io_serial_;
    if (!io_.connected || io_client_ < 0) {
        io_done_[n] = "iocontrol is not connected";
        return n;
    }
    if (words[0] == "ESTOP_ON" || words[0] == "ESTOP_OFF")
        io_estop_.sent(n, words[0] == "ESTOP_ON");
    std::string line = "IOCMD " + std::to_string(n);
    for (const std::string& w : words)
        line += " " + w;
    server_->send_line(io_client_, line);
    return n;
}

int Task::io_result(long serial, std::string* err)
{
    auto it = io_done_.find(serial);
    if (it == io_done_.end())
        return 0;
    int r = it->second.empty() ? 1 : -1;
    if (err)
        *err = it->second;
    io_done_.erase(it);
    return r;
}

void Task::execute_queue()
{
    auto& q = canon_->queue();
    auto sent_at = Clock::now();
    while (!q.empty()) {
        if (paused_ || aborted_)
            return;
        Item& it = q.front();
        if (it.wait_motion && !motion_idle())
            return;
        switch (it.kind) {
        case Item::Motion: {
            int c = it.cmd.command;
            bool move = c == MOTCMD_SET_LINE || c == MOTCMD_SET_CIRCLE || c == MOTCMD_PROBE || c == MOTCMD_RIGID_TAP;
            if (move) {
                if (state_ != TaskState::ON) {
                    abort_task("");
                    return;
                }
                if (mst_.depth + queued_since_status_ >= MOTION_QUEUE_LIMIT || mst_.queueFull)
                    return;
            }
            std::string err;
            if (!send_motion(it.cmd, &err)) {
                abort_task(current_line_ > 0 ? "line " + std::to_string(it.line) + ": " + err : err);
                return;
            }
            if (move)
                ++queued_since_status_;
            break;
        }
        case Item::Io: {
            if (queue_io_serial_ == 0) {
                queue_io_serial_ = io_send(it.io);
            }
            std::string err;
            int r = io_result(queue_io_serial_, &err);
            if (r == 0)
                return;
            queue_io_serial_ = 0;
            if (r < 0) {
                abort_task("iocontrol: " + it.io[0] + ": " + err);
                return;
            }
            break;
        }
        case Item::Delay:
            if (!delay_started_) {
                delay_started_ = true;
                delay_end_ = Clock::now() + microseconds(static_cast<long>(it.seconds * 1e6));
            }
            if (Clock::now() < delay_end_)
                return;
            delay_started_ = false;
            break;
        case Item::Message:
            server_->broadcast(it.msg_kind, it.text);
            break;
        case Item::Stop:
            paused_ = true;
            q.pop_front();
            return;
        case Item::OptionalStop:
            if (optional_stop_) {
                paused_ = true;
                q.pop_front();
                return;
            }
            break;
        case Item::End:
            q.pop_front();
            finish_program();
            return;
        }
        q.pop_front();
        // sending takes a servo period each: give the bus and status their turn
        if (Clock::now() - sent_at > milliseconds(50)) {
            read_motion();
            queued_since_status_ = 0;
            return;
        }
        if (queued_since_status_ >= 50) {
            read_motion();
            queued_since_status_ = 0;
        }
    }
    queued_since_status_ = 0;
}

void Task::finish_program()
{
    program_running_ = false;
    reading_ = false;
    step_mode_ = step_hold_ = false;
    if (!interp_->save_parameters())
        error_all(interp_->error().to_string());
}

void Task::read_ahead()
{
    if (!reading_ || paused_ || in_interp_)
        return;
    if (step_mode_ && step_hold_)
        return;
    auto& q = canon_->queue();
    for (int n = 0; n < READ_AHEAD_PER_CYCLE && reading_ && static_cast<int>(q.size()) < cfg_.interp_max_len;
         ++n) {
        in_interp_ = true;
        aborted_ = false;
        rs274::Status s = interp_->step();
        in_interp_ = false;
        if (aborted_) {
            aborted_ = false;
            q.clear();
            interp_->reset();
            return;
        }
        if (s == rs274::Status::ERROR) {
            std::string e = interp_->error().to_string();
            abort_task(e);
            return;
        }
        if (s == rs274::Status::END) {
            reading_ = false;
            if (q.empty() || q.back().kind != Item::End) {
                Item end;
                end.kind = Item::End;
                end.wait_motion = true;
                q.push_back(end);
            }
            return;
        }
        if (step_mode_) {
            step_hold_ = true;
            return;
        }
    }
}

void Task::start_next_mdi()
{
    if (mdi_running_) {
        if (!canon_->queue().empty() || !motion_idle() || paused_)
            return;
        mdi_running_ = false;
        server_->reply(mdi_current_.client, mdi_current_.serial, "DONE");
    }
    if (mdi_queue_.empty() || in_interp_)
        return;
    if (mode_ != TaskMode::MDI || state_ != TaskState::ON) {
        for (const MdiRequest& m : mdi_queue_)
            server_->reply(m.client, m.serial, "ERROR MDI: not in MDI mode with the machine on");
        mdi_queue_.clear();
        return;
    }
    mdi_current_ = mdi_queue_.front();
    mdi_queue_.pop_front();
    synch_interp_if_idle();
    in_interp_ = true;
    aborted_ = false;
    rs274::Status s = interp_->execute_mdi(mdi_current_.line);
    in_interp_ = false;
    if (aborted_) {
        aborted_ = false;
        canon_->queue().clear();
        interp_->reset();
        server_->reply(mdi_current_.client, mdi_current_.serial, "ERROR MDI: aborted");
        return;
    }
    if (s == rs274::Status::ERROR) {
        std::string e = interp_->error().to_string();
        error_all(e);
        server_->reply(mdi_current_.client, mdi_current_.serial, "ERROR " + e);
        canon_->queue().clear();
        interp_->reset();
        return;
    }
    mdi_running_ = true;
}

void Task::check_waiters()
{
    for (size_t i = 0; i < waiters_.size();) {
        std::string err;
        int r = waiters_[i].check(err);
        if (r == 0) {
            ++i;
            continue;
        }
        server_->reply(waiters_[i].client, waiters_[i].serial, r > 0 ? "DONE" : "ERROR " + err);
        waiters_.erase(waiters_.begin() + static_cast<long>(i));
    }
}

void Task::synch_interp_if_idle()
{
    if (!canon_->queue().empty())
        return;
    // A command sent this cycle (the switch to COORD that MDI or AUTO mode asks for, a
    // machine on) shows in the status only a servo cycle or two later; a position read
    // before that can be the one from before (motion's motor offsets not yet applied).
    // Wait for it, a few milliseconds at most, rather than start from a stale position.
    auto deadline = Clock::now() + milliseconds(200);
    while (static_cast<int32_t>(mst_.heartbeat - busy_until_heartbeat_) < 0 && Clock::now() < deadline) {
        usleep(1000);
        read_motion();
    }
    if (motion_idle())
        synch_interp();
}

void Task::synch_interp()
{
    rs274::Pos p{};
    for (int a = 0; a < rs274::NUM_AXES; ++a)
        p[a] = mst_.carte_pos_cmd.v[a];
    interp_->set_machine_position(p);
    canon_->set_position(p);
}

void Task::abort_task(const std::string& why)
{
    if (!why.empty())
        error_all(why);
    send_motion(mcmd(MOTCMD_ABORT), nullptr);
    motion_command off = mcmd(MOTCMD_SPINDLE_OFF);
    off.spindle = -1;
    if (cfg_.spindles > 0)
        send_motion(off, nullptr);
    io_send({"ABORT"});
    canon_->queue().clear();
    queue_io_serial_ = 0;
    delay_started_ = false;
    if (in_interp_)
        aborted_ = true;   // the interpreter call in progress ends, then it is reset
    else
        interp_->reset();
    reading_ = false;
    program_running_ = false;
    paused_ = false;
    step_mode_ = step_hold_ = false;
    if (mdi_running_) {
        mdi_running_ = false;
        server_->reply(mdi_current_.client, mdi_current_.serial, "ERROR MDI: aborted");
    }
    for (const MdiRequest& m : mdi_queue_)
        server_->reply(m.client, m.serial, "ERROR MDI: aborted");
    mdi_queue_.clear();
    if (!interp_->save_parameters())
        server_->broadcast("ERROR", interp_->error().to_string());
}

// ESTOP and OFF (motion.md 16): motion stopped and disabled, amplifiers off, lube
// off, task aborted, the volatile-home joints unhomed; ESTOP also drops iocontrol's
// user-enable-out.
void Task::machine_off(bool estop)
{
    send_motion(mcmd(MOTCMD_ABORT), nullptr);
    if (estop)
        io_send({"ESTOP_ON"});
    for (int j = 0; j < cfg_.joints; ++j) {
        motion_command c = mcmd(MOTCMD_JOINT_DISABLE_AMPLIFIER);
        c.joint = j;
        send_motion(c, nullptr);
    }
    send_motion(mcmd(MOTCMD_DISABLE), nullptr);
    io_send({"LUBE", "0"});
    abort_task("");
    motion_command u = mcmd(MOTCMD_JOINT_UNHOME);
    u.joint = -2;   // the VOLATILE_HOME joints
    send_motion(u, nullptr);
}

void Task::do_estop_actions()
{
    machine_off(true);
}

void Task::set_state(TaskState s)
{
    requested_state_ = s;
    switch (s) {
    case TaskState::ESTOP:
        machine_off(true);
        break;
    case TaskState::ESTOP_RESET:
        io_send({"ESTOP_OFF"});
        io_send({"LUBE", "0"});
        abort_task("");
        break;
    case TaskState::OFF:
        machine_off(false);
        break;
    case TaskState::ON:
        send_motion(mcmd(MOTCMD_ENABLE), nullptr);
        for (int j = 0; j < cfg_.joints; ++j) {
            motion_command c = mcmd(MOTCMD_JOINT_ENABLE_AMPLIFIER);
            c.joint = j;
            send_motion(c, nullptr);
        }
        io_send({"LUBE", "1"});
        break;
    }
}

bool Task::wait_queue_drained()
{
    while (!aborted_ && (!canon_->queue().empty() || !motion_idle() || paused_)) {
        cycle(true);
        if (state_ != TaskState::ON) {
            aborted_ = true;
            break;
        }
    }
    return !aborted_;
}

rs274::ProbeResult Task::probe_result()
{
    rs274::ProbeResult r;
    r.position = canon_->position();
    if (!wait_queue_drained())
        return r;
    read_motion();
    for (int a = 0; a < rs274::NUM_AXES; ++a)
        r.position[a] = mst_.probeTripped ? mst_.probedPos.v[a] : mst_.carte_pos_cmd.v[a];
    r.tripped = mst_.probeTripped != 0;
    return r;
}

double Task::wait_input(int index, bool analog, rs274::WaitType type, double timeout)
{
    if (!wait_queue_drained())
        return -1;
    auto value = [&]() -> double {
        if (analog)
            return index >= 0 && index < MOTION_MAX_AIO ? mst_.analog_input[index] : 0;
        return index >= 0 && index < MOTION_MAX_DIO ? mst_.synch_di[index] : 0;
    };
    if (type == rs274::WaitType::IMMEDIATE)
        return value();
    auto deadline = Clock::now() + microseconds(static_cast<long>(std::max(0.0, timeout) * 1e6));
    double prev = value();
    for (;;) {
        double v = value();
        bool met = (type == rs274::WaitType::HIGH && v != 0) || (type == rs274::WaitType::LOW && v == 0) ||
                   (type == rs274::WaitType::RISE && prev == 0 && v != 0) ||
                   (type == rs274::WaitType::FALL && prev != 0 && v == 0);
        if (met)
            return v;
        if (Clock::now() >= deadline || aborted_)
            return -1;
        prev = v;
        cycle(true);
    }
}

int Task::user_m_code(int code, const std::string& path, double p, double q)
{
    if (!wait_queue_drained())
        return -1;
    char pa[40], qa[40];
    std::snprintf(pa, sizeof pa, "%f", p);
    std::snprintf(qa, sizeof qa, "%f", q);
    pid_t pid = fork();
    if (pid < 0) {
        error_all("M" + std::to_string(code) + ": cannot start " + path);
        return -1;
    }
    if (pid == 0) {
        execl(path.c_str(), path.c_str(), pa, qa, static_cast<char*>(nullptr));
        _exit(127);
    }
    int st = 0;
    for (;;) {
        pid_t r = waitpid(pid, &st, WNOHANG);
        if (r == pid)
            break;
        if (aborted_) {
            kill(pid, SIGTERM);
            waitpid(pid, &st, 0);
            return -1;
        }
        cycle(true);
    }
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

bool Task::hal_value(const std::string& name, double& value)
{
    // #<_hal[...]> ([RS274NGC]HAL_PIN_VARS): the value when the interpreter reads the line
    return inihal_ && read_hal_value(name, value);
}

}  // namespace hal::task
