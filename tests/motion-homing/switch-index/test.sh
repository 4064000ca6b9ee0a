# Switch + index with an encoder that zeroes its count at the index. A simulated
# servo: pid (command joint.0.motor-pos-cmd, feedback encoder.0.position) drives a
# quadrature stepgen in velocity mode (100 us base thread) whose phases feed
# encoder.0; stepgen.0.position-fb is the carriage position. comp.0 (above 1.0) is
# the home switch, comp.1 (above 1.3, servo thread: comp uses FP) drives phase-Z. joint.0.index-enable is wired to
# encoder.0.index-enable and pid.0.index-enable. Search +2, latch +0.5, USE_INDEX,
# HOME_OFFSET 0.25, HOME 0.75: the index reads 0.25, HOME is carriage position 1.8.
. ../lib.sh
halcmd -f <<'HAL' || exit 1
loadrt trivkins coordinates=x
loadrt motmod base_period_nsec=100000 servo_period_nsec=1000000 num_joints=1
loadrt stepgen step_type=2 ctrl_type=v
loadrt encoder num_chan=1
loadrt pid num_chan=1
loadrt comp count=2
loadrt sampler depth=40000 cfg=sf
setp stepgen.0.position-scale 1000
setp stepgen.0.maxvel 8
setp stepgen.0.maxaccel 1000
setp stepgen.0.enable TRUE
setp encoder.0.position-scale 1000
setp pid.0.Pgain 100
setp pid.0.FF1 1
setp pid.0.maxoutput 8
setp pid.0.enable TRUE
setp comp.0.in0 1.0
setp comp.1.in0 1.3
net qa stepgen.0.phase-A => encoder.0.phase-A
net qb stepgen.0.phase-B => encoder.0.phase-B
net carriage stepgen.0.position-fb => comp.0.in1 comp.1.in1
net home comp.0.out => joint.0.home-sw-in
net z comp.1.out => encoder.0.phase-Z
net idx joint.0.index-enable <=> encoder.0.index-enable pid.0.index-enable
net fb encoder.0.position => pid.0.feedback joint.0.motor-pos-fb
net cmd joint.0.motor-pos-cmd => pid.0.command
net vcmd joint.0.vel-cmd => pid.0.command-deriv
net vel pid.0.output => stepgen.0.velocity-cmd
net st joint.0.home-state => sampler.0.pin.0
net carriage => sampler.0.pin.1
addf stepgen.make-pulses base-thread
addf encoder.update-counters base-thread
addf comp.1 servo-thread
addf stepgen.capture-position servo-thread
addf encoder.capture-position servo-thread
addf comp.0 servo-thread
addf motion-command-handler servo-thread
addf motion-controller servo-thread
addf pid.0.do-pid-calcs servo-thread
addf stepgen.update-freq servo-thread
addf sampler.0 servo-thread
start
HAL
joint_limits 0
motcmd set-joint-ferror 0 1 && motcmd set-joint-min-ferror 0 1 || exit 1
motcmd set-joint-homing 0 0.25 0.75 -1 2 0.5 2 0 || exit 1
motcmd enable || exit 1
motcmd home 0 || exit 1
motcmd wait-homed 30 || exit 1
sleep 0.5	# the servo settles
motcmd errors
stop_and_sample "$TEST_TMPDIR/s"
echo "home-state: $(states "$TEST_TMPDIR/s" 1)"
echo "joint.0.homed $(halcmd getp joint.0.homed) index-enable $(halcmd getp joint.0.index-enable)"
pos joint.0.pos-cmd 3
pos joint.0.motor-offset 3
pos stepgen.0.position-fb 2
halrun -U
