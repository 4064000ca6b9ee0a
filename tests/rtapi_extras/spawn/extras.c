/* Uses the simulated flavor's RTAPI extras at init and shows the results on pins. */
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
MODULE_LICENSE("GPL");
static char *touch = "";
RTAPI_MP_STRING(touch, "file for the spawned touch(1) to create");
static int comp_id;
static hal_s32_t **pins;	/* spawn status, open result, kernelspace, pll outside a task */

int rtapi_app_main(void)
{
	char *argv[] = { "touch", touch, NULL };
	char *envp[] = { "PATH=/usr/bin:/bin", NULL };
	pid_t pid;
	int status = -1, fd;

	comp_id = hal_init("extras");
	if (comp_id < 0)
		return comp_id;
	pins = hal_malloc(4 * sizeof(*pins));
	if (!pins || hal_pin_s32_new("extras.spawn-status", HAL_OUT, &pins[0], comp_id) ||
	    hal_pin_s32_new("extras.open-ok", HAL_OUT, &pins[1], comp_id) ||
	    hal_pin_s32_new("extras.kernelspace", HAL_OUT, &pins[2], comp_id) ||
	    hal_pin_s32_new("extras.pll-refused", HAL_OUT, &pins[3], comp_id)) {
		hal_exit(comp_id);
		return -1;
	}
	if (rtapi_spawnp_as_root(&pid, "touch", NULL, NULL, argv, envp) == 0)
		waitpid(pid, &status, 0);
	*pins[0] = status;
	fd = rtapi_open_as_root("/dev/null", O_RDONLY);
	*pins[1] = fd >= 0;
	if (fd >= 0)
		close(fd);
	*pins[2] = rtapi_is_kernelspace();
	/* init code is no task: no reference, and a correction is refused */
	*pins[3] = rtapi_task_pll_get_reference() == 0 && rtapi_task_pll_set_correction(1000) == -EINVAL;
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
