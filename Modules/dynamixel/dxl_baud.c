/* dxl_baud.c: arbitrary serial rates through termios2 / BOTHER (Linux). Separate file because
 * <asm/termbits.h> cannot be included together with <termios.h>. */
#include <asm/ioctls.h>
#include <asm/termbits.h>

int ioctl(int fd, unsigned long request, ...);
int dxl_port_set_custom_baud_(int fd, int baud);

int dxl_port_set_custom_baud_(int fd, int baud) {
  struct termios2 t;
  if (ioctl(fd, TCGETS2, &t) != 0) return -1;
  t.c_cflag &= ~(tcflag_t)CBAUD;
  t.c_cflag |= BOTHER;
  t.c_ispeed = (speed_t)baud;
  t.c_ospeed = (speed_t)baud;
  if (ioctl(fd, TCSETS2, &t) != 0) return -1;
  return 0;
}
