# estop, machine on/off, the task modes and teleop/joint through halui's IN pins:
# task's state (emcbus) follows, and so do halui's OUT pins.
. ../lib.sh
machine_start
echo "start: estop $(pin estop.is-activated) on $(pin machine.is-on) manual $(pin mode.is-manual) idle $(pin program.is-idle)"
press estop.reset
bus wait task.state ESTOP_RESET 10 || exit 1
wait_pin estop.is-activated FALSE
press machine.on
bus wait task.state ON 10 || exit 1
wait_pin machine.is-on TRUE
echo "on: task.state $(bus status task.state), units-per-mm $(pin machine.units-per-mm)"
press mode.mdi
bus wait task.mode MDI 5 || exit 1
wait_pin mode.is-mdi TRUE
echo "mdi: manual $(pin mode.is-manual) auto $(pin mode.is-auto) mdi $(pin mode.is-mdi)"
press mode.auto
bus wait task.mode AUTO 5 || exit 1
wait_pin mode.is-auto TRUE
press mode.manual
bus wait task.mode MANUAL 5 || exit 1
wait_pin mode.is-manual TRUE
echo "manual: joint $(pin mode.is-joint) teleop $(pin mode.is-teleop) homed $(pin joint.0.is-homed)"
press home-all
bus wait traj.all_homed 1 10 || exit 1
wait_pin joint.2.is-homed TRUE
wait_pin joint.selected.is-homed TRUE
press mode.joint
bus wait traj.mode FREE 5 || exit 1
wait_pin mode.is-joint TRUE
press mode.teleop
bus wait traj.mode TELEOP 5 || exit 1
wait_pin mode.is-teleop TRUE
echo "teleop: joint $(pin mode.is-joint) teleop $(pin mode.is-teleop)"
press machine.off
wait_pin machine.is-on FALSE
echo "off: task.state $(bus status task.state) estop $(pin estop.is-activated)"
press estop.activate
bus wait task.state ESTOP 5 || exit 1
wait_pin estop.is-activated TRUE
echo "estop: task.state $(bus status task.state) homed $(pin joint.0.is-homed)"
machine_stop
