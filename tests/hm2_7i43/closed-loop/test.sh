# loop.hal with its firmware file made first (HAL_FIRMWARE_PATH must be in
# rtapi_app's environment, i.e. halrun's).
. ../../helpers/hm2-bitfile.sh
hm2_bitfile hm2/7i43/cl.BIT 3s400tq144
halrun -f loop.hal
