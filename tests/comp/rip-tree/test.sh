# Build a hand-written module with only -I RIP/include (as LinuxCNC Makefiles do), then load it.
set -e
. ../private-rtlib.sh
ls "$rip/lib" | grep '\.a$'	# the libraries (lib/ also holds the Python module)
cat > "$tmp/ripmod.c" <<'C'
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
MODULE_LICENSE("GPL");
static int comp_id;
static hal_s32_t **out;	/* the pin pointer lives in HAL memory */
int rtapi_app_main(void)
{
	comp_id = hal_init("ripmod");
	if (comp_id < 0)
		return comp_id;
	out = hal_malloc(sizeof(*out));
	if (!out || hal_pin_s32_new("ripmod.out", HAL_OUT, out, comp_id)) {
		hal_exit(comp_id);
		return -1;
	}
	**out = 7;
	hal_ready(comp_id);
	return 0;
}
void rtapi_app_exit(void) { hal_exit(comp_id); }
C
cc -shared -fPIC -DRTAPI -I "$rip/include" -o "$tmp/rtlib/ripmod.so" "$tmp/ripmod.c"
HAL_RTLIB_DIR=$tmp/rtlib halcmd loadrt ripmod
halcmd getp ripmod.out
halrun -U
