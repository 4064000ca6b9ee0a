component ucount "userspace counter";
pin out s32 n;
pin in bit stop_;
option userspace yes;
option userinit yes;
license "GPL";
;;
#include <unistd.h>
static int limit = 3;
void userinit(int argc, char **argv)
{
	if (argc > 1)
		limit = atoi(argv[1]);
}
void user_mainloop(void)
{
	int i;
	for (i = 0; i < limit; i++) {
		FOR_ALL_INSTS() {
			n++;
		}
		usleep(1000);
	}
}
