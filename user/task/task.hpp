// SPDX-License-Identifier: GPL-2.0-or-later
// task.hpp - the task controller (docs/task.md): one thread, one loop. Each cycle it
// reads motion's status and the bus, carries out client commands, runs the work
// queue the interpreter filled (moves into motion's queue as long as there is room,
// io commands one at a time, waits), lets the interpreter read ahead, and answers
// the clients whose commands have finished.
//
// Interpreter calls that must read the machine (probe, M66, user M codes) run nested
// cycles (cycle(true)) until the queue has drained; meanwhile commands that would
// re-enter the interpreter are refused as busy, and ABORT/ESTOP end the wait.
#pragma once

#include <chrono>
#include <csignal>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bus/server.hpp"
#include "inihal.hpp"
#include "io_estop.hpp"
#include "motion_client.hpp"
#include "rs274/interp.hpp"
#include "task_canon.hpp"
#include "task_config.hpp"
#include "task_state.hpp"

namespace hal::task {

using Clock = std::chrono::steady_clock;

class Task : public bus::Server::Handler, public TaskCanon::Host {
public:
    Task(TaskConfig cfg, rs274::Config icfg, std::unique_ptr<MotionClient> motion,
         std::unique_ptr<bus::Server> server);
    ~Task() override;

    // Interpreter init (parameter file, tool table, startup code); false + message.
    bool init(std::string& error);
    // The inihal pins (milltask's HAL component); without them task reads no HAL.
    void set_inihal(std::unique_ptr<IniHal> h) { inihal_ = std::move(h); }
    // Runs until *stop becomes non-zero; saves the parameter file (and the position
    // file) at the end.
    void run(volatile std::sig_atomic_t* stop);

    // bus::Server::Handler
    void on_command(int client, const bus::Request& req) override;
    void on_io_line(int client, const std::string& line) override;
    void on_connect(int client, bus::Role role) override;
    void on_disconnect(int client, bus::Role role) override;

    // TaskCanon::Host
    rs274::ProbeResult probe_result() override;
    double wait_input(int index, bool analog, rs274::WaitType type, double timeout) override;
    int user_m_code(int code, const std::string& path, double p, double q) override;
    bool hal_value(const std::string& name, double& value) override;

private:
    // A client's command that finishes later: check() returns 1 done, -1 failed (err set), 0 not yet.
    struct Waiter {
        int client;
        long serial;
        std::function<int(std::string& err)> check;
    };
    struct IoState {
        bool connected = false;
        bool mist = false, flood = false, lube = false, lube_level = false;
        int tool = 0, pocket_prepped = -1, prep_tool = 0, from_pocket = 0;
        std::vector<std::string> tools;     // tool table lines (IOTOOLS)
        size_t tools_expected = 0;          // lines of an IOTOOLS block still to come
        std::vector<std::string> tools_in;
    };
    struct MdiRequest {
        int client;
        long serial;
        std::string line;
    };

    void cycle(bool nested);
    void read_motion();
    void take_motion_errors();
    void configure_motion();
    void apply_inihal();
    void save_positions();
    void update_state();
    void refresh_interp_state();
    void ensure_motion_mode();
    void execute_queue();
    void read_ahead();
    void start_next_mdi();
    void check_waiters();
    void finish_program();

    // motion and io
    bool send_motion(motion_command c, std::string* err = nullptr);
    motion_command mcmd(int type) const;
    bool motion_idle() const;
    bool motion_enabled() const { return (mst_.motionFlag & MOTION_FLAG_ENABLE) != 0; }
    // how long a STATE command may wait for motion to show its effect
    Clock::time_point state_deadline() const
    {
        return Clock::now() + std::chrono::milliseconds(static_cast<long>(cfg_.comm_timeout * 1000) + 500);
    }
    bool all_homed() const;
    long io_send(const std::vector<std::string>& words);
    // io command state: 0 pending, 1 done, -1 failed (text in *err)
    int io_result(long serial, std::string* err);

    // state changes
    void set_state(TaskState s);
    void do_estop_actions();
    void machine_off(bool estop);
    void abort_task(const std::string& why);
    // the interpreter starts from motion's commanded position (an idle, settled motion only)
    void synch_interp_if_idle();
    void synch_interp();

    // commands (task_commands.cpp)
    std::string cmd_state(int client, const bus::Request& r);
    std::string cmd_mode(const bus::Request& r);
    std::string cmd_program(int client, const bus::Request& r);
    std::string cmd_manual(const bus::Request& r);
    std::string cmd_io(int client, const bus::Request& r);
    std::string cmd_setting(const bus::Request& r);

    // status (task_status.cpp)
    bus::StatusLines status_lines() const;

    void error_all(const std::string& text);
    bool wait_queue_drained();   // nested cycles; false when aborted meanwhile

    TaskConfig cfg_;
    std::unique_ptr<MotionClient> motion_;
    std::unique_ptr<bus::Server> server_;
    std::unique_ptr<TaskCanon> canon_;
    std::unique_ptr<rs274::Interp> interp_;
    std::unique_ptr<IniHal> inihal_;

    motion_status mst_{};
    bool motion_ready_ = false;        // motion answered and took the INI settings
    uint32_t first_heartbeat_ = 0;
    bool have_first_heartbeat_ = false;
    uint32_t busy_until_heartbeat_ = 0;   // status older than this may not show the last send
    int queued_since_status_ = 0;

    TaskState requested_state_ = TaskState::ESTOP;
    TaskState state_ = TaskState::ESTOP;
    TaskMode mode_ = TaskMode::MANUAL;
    InterpState interp_state_ = InterpState::IDLE;
    bool teleop_wanted_ = true;
    Clock::time_point last_mode_send_{};

    IoState io_;
    IoEstop io_estop_;   // io's estop reports that count (io_estop.hpp)
    bool last_io_estop_ = true;
    // until then an ESTOP_RESET waits for iocontrol to (re)connect (task start-up, io restart)
    Clock::time_point io_wait_until_ = Clock::now() + std::chrono::seconds(5);
    int io_client_ = -1;
    long io_serial_ = 0;
    std::map<long, std::string> io_done_;   // serial -> "" done / error text
    long queue_io_serial_ = 0;              // the io command the queue waits for

    // program / MDI
    std::string program_file_;
    bool program_open_ = false;
    bool reading_ = false;        // the interpreter reads ahead (AUTO run)
    bool program_running_ = false;
    bool paused_ = false;         // PAUSE or M0/M1
    bool step_mode_ = false, step_hold_ = false;
    bool optional_stop_ = false, block_delete_ = false;
    bool in_interp_ = false;      // inside Interp::step/execute_mdi
    bool aborted_ = false;        // an abort happened during in_interp_
    int motion_line_ = 0;
    int current_line_ = 0;
    bool delay_started_ = false;
    Clock::time_point delay_end_{};
    std::deque<MdiRequest> mdi_queue_;
    bool mdi_running_ = false;
    MdiRequest mdi_current_{};
    std::vector<Waiter> waiters_;
    int debug_ = 0;
    unsigned long heartbeat_ = 0;
    std::string last_error_;
};

}  // namespace hal::task
