# what task would send from the INI file: [JOINT_n] and [AXIS_L] limits, homing
# (HOME_OFFSET HOME HOME_FINAL_VEL HOME_SEARCH_VEL HOME_LATCH_VEL flags HOME_SEQUENCE)
set-joint-limits 0 -10 40
set-joint-limits 1 -30 30
set-joint-limits 2 -20 5
set-joint-vel 0 20
set-joint-vel 1 20
set-joint-vel 2 10
set-joint-acc 0 200
set-joint-acc 1 200
set-joint-acc 2 100
set-joint-ferror 0 1
set-joint-ferror 1 1
set-joint-ferror 2 1
set-joint-min-ferror 0 0.5
set-joint-min-ferror 1 0.5
set-joint-min-ferror 2 0.5
set-axis-limits x -10 40
set-axis-limits y -30 30
set-axis-limits z -20 5
set-axis-vel x 20
set-axis-vel y 20
set-axis-vel z 10
set-axis-acc x 200
set-axis-acc y 200
set-axis-acc z 100
# X: switch is joint coordinate 10, then to 5; Y: negative search, switch is -20, then 0
# Z: first (sequence 0), switch is 0, then -1
set-joint-homing 0 10 5 -1 8 1 0 1
set-joint-homing 1 -20 0 -1 -8 -1 0 1
set-joint-homing 2 0 -1 -1 4 0.5 0 0
set-vel-limit 20
set-acc 200
