/* hubo_emulator: the Hubo2+'s boards on SocketCAN buses, for tests and bring-up without the robot.
 *
 *   hubo_emulator [--robot NAME] [--iface BUS=NAME]... [--unhomed] [--tau S] [--no-timing]
 *                 [--drop P] [--corrupt P] [--delay S] [--dead BOARD]... [--error BOARD]...
 *                 [--seed N] [--stdin] [--realtime] [--quiet] [--sim-id N]
 *
 * The boards are the body's can.lua (ROBOT, default hubo2plus) on its interfaces (can0, can1; a
 * real kernel's vcan works; with HUBO_FAKE_CAN=1 in the environment, the fake SocketCAN of
 * Platforms/Hubo/tests/fake_socketcan.c, linked in, for a kernel without AF_CAN). Motor boards start at encoder zero with FETs and controllers off, homed
 * (--unhomed: home state 0 until a homing command), and move first-order towards their reference
 * (time constant --tau, capped at the channel's max_speed) while FETs and controller are on; after
 * H_SET_CTRL_MODE 1 a board reads its reference frame as currents and its joints turn as emu.h says
 * (emu_step), H_SET_CTRL_MODE 0 puts it back in position mode holding where it is.
 *
 * Timing model of a 1 Mbit/s bus (the table's bitrate): every frame occupies its bus for its exact
 * bit count (hcan_frame_bits: stuff bits included) at the bit rate, one frame at a time; a board
 * answers 20 us after the request's last bit, and its reply leaves when the bus is free and arrives
 * at its last bit (--no-timing: at once). Frames queue in order (no arbitration by id).
 * Faults: --drop P (no answer), --corrupt P (an answer is damaged, in equal shares: a bit error --
 * the CRC catches it, every node sees an error frame, the board sends it again; a wrong DLC; the
 * number of a board that is not on the bus), --delay S (added before every answer), --dead BOARD
 * (never answers), --error BOARD (its status reports a big position error).
 * BOARD: a name of can.lua (JMC2) or a number (0x02).
 * --stdin reads commands, one per line: dead BOARD | alive BOARD | error BOARD FAULTS LIMITS |
 *   ft BOARD MX MY FZ | imu ROLL PITCH ROLL_RATE PITCH_RATE | power V A W | move BOARD CH COUNTS (a
 *   hand moves the joint: its encoder jumps there) | stats | quit.
 * stats prints per board "board NAME bus B number N ref R0 R1 enc E0 E1 fet F ctrl C home H dead D refs N
 *   mode M amps A0 A1 mode_frames N cur_refs N enc_reqs N" (mode 0 position, 1 current: H_SET_CTRL_MODE; amps the
 *   current reference in current mode, emu.h says what a current does),
 * "sensor NAME ..." for sensor and power boards, "silent NAME ..." for boards it does not emulate (the
 * Hubo2+ neck: formats unknown), per bus "bus B frames_in N frames_out M bits BITS load_pct L", totals
 * (with `unparsed`: host frames it could not parse), then "end".
 * --sim-id N: hardware in the loop: the sim DCM's robot N moves the joints and gives the F/T and
 *   IMU boards' readings instead of the first-order model (emu_sim.h); the boards start homed.
 * Prints "hubo_emulator: ready" on stderr when its sockets are bound.
 */
#include "emu.h"
#include "emu_sim.h"
#include "../hio_sys.h"
#include "../tests/fake_socketcan.h"

#include <errno.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <math.h>
#include <net/if.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#define QMAX 4096
#define PROCESS_TIME 20e-6   /* s from a request's last bit to the board's answer */

typedef struct pending {
  double due;
  int bus;
  hcan_frame f;
} pending;

static struct {
  int timing, quiet, use_stdin;
  double p_drop, p_corrupt, delay;
  ht_table table;
  emu_world w;
  int fd[HT_BUS_MAX];
  double busy[HT_BUS_MAX];                 /* s, the bus is occupied until then */
  uint64_t frames_in[HT_BUS_MAX], frames_out[HT_BUS_MAX], bits[HT_BUS_MAX];
  double t0;
  pending q[QMAX];
  int nq;
  unsigned long n_rx, n_tx, n_dropped, n_corrupted, n_overflow;
} E;
static volatile sig_atomic_t stop;

static void on_signal(int s) { (void)s; stop = 1; }

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static double uniform(void) { return rand() / (RAND_MAX + 1.0); }

/* the sockets' system calls: libc's, or the fake SocketCAN's (HUBO_FAKE_CAN=1) */
static hio_sys io = HIO_SYS_LIBC;

static int open_bus(const char *name, char *err, size_t n) {
  const int s = io.socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (s < 0) {
    snprintf(err, n, "socket(PF_CAN): %s", strerror(errno));
    return -1;
  }
  struct ifreq ifr;
  memset(&ifr, 0, sizeof ifr);
  snprintf(ifr.ifr_name, sizeof ifr.ifr_name, "%s", name);
  if (io.ioctl(s, SIOCGIFINDEX, &ifr) < 0) {
    snprintf(err, n, "interface %s: %s", name, strerror(errno));
    io.close(s);
    return -1;
  }
  struct sockaddr_can a = { .can_family = AF_CAN, .can_ifindex = ifr.ifr_ifindex };
  if (io.bind(s, (struct sockaddr *)&a, sizeof a) < 0) {
    snprintf(err, n, "bind %s: %s", name, strerror(errno));
    io.close(s);
    return -1;
  }
  /* the host's frames only: commands 0x001, sensor requests 0x002, references 0x010..0x03F */
  const canid_t m = CAN_SFF_MASK | CAN_EFF_FLAG | CAN_RTR_FLAG;
  struct can_filter flt[] = { { 0x001, m }, { 0x002, m }, { 0x010, 0x7F0 | CAN_EFF_FLAG | CAN_RTR_FLAG },
                              { 0x020, 0x7F0 | CAN_EFF_FLAG | CAN_RTR_FLAG }, { 0x030, 0x7F0 | CAN_EFF_FLAG | CAN_RTR_FLAG } };
  io.setsockopt(s, SOL_CAN_RAW, CAN_RAW_FILTER, flt, sizeof flt);
  return s;
}

/* ---------------------------------------------------------------- the bus timing model */

/* A frame occupies bus b from max(ready, busy) for its bits; returns when its last bit is on. */
static double occupy(int b, const hcan_frame *f, double ready) {
  const int bits = hcan_frame_bits(f);
  E.bits[b] += (uint64_t)bits;
  if (!E.timing) return ready;
  const double start = ready > E.busy[b] ? ready : E.busy[b];
  E.busy[b] = start + bits / E.table.bitrate;
  return E.busy[b];
}

/* The board numbers in use on bus b (motor boards and sensors alike). */
static int in_use(int b, int num) {
  for (int k = 0; k < E.w.n; k++)
    if (E.w.b[k].def->bus == b && E.w.b[k].def->number == num) return 1;
  return 0;
}

/* Damages a reply: 0 it stays as it is but costs an error frame and a retransmission (what a bit
 * error does on CAN: the CRC catches it); 1 truncated (a wrong DLC); 2 the same reply from a board
 * number nobody on the bus has (a misset DIP switch). Returns the kind. */
static int damage(int b, hcan_frame *f) {
  const int kind = rand() % 3;
  int num;
  hcan_classify(f, &num);
  if (kind == 1 && f->dlc > 0) {
    f->dlc = (uint8_t)(rand() % f->dlc);
  } else if (kind == 2 && num >= 0) {
    int other = num;
    for (int t = 1; t < HCAN_SENSOR_MAX && (other == num || in_use(b, other)); t++) other = (num + t) % HCAN_SENSOR_MAX;
    f->id = f->id - (uint32_t)num + (uint32_t)other;
  } else {
    return 0;
  }
  return kind;
}

static void queue_frame(int bus, const hcan_frame *f, double due) {
  if (E.nq >= QMAX) {
    E.n_overflow++;
    return;
  }
  pending *p = &E.q[E.nq++];
  p->f = *f;
  p->bus = bus;
  p->due = due;
}

static void enqueue(int bus, const hcan_frame *f, double ready) {
  if (E.p_drop > 0 && uniform() < E.p_drop) {
    E.n_dropped++;
    return;
  }
  hcan_frame out = *f;
  if (E.p_corrupt > 0 && uniform() < E.p_corrupt) {
    E.n_corrupted++;
    if (damage(bus, &out) == 0) {
      /* the damaged transmission, then the error frame every node sees, then the retry */
      const double err_end = occupy(bus, &out, ready + E.delay) + 20 / E.table.bitrate;
      if (E.timing) E.busy[bus] = err_end;
      hcan_frame ef = { .id = HCAN_ERR | CAN_ERR_PROT, .dlc = 8 };
      ef.data[2] = CAN_ERR_PROT_BIT;
      queue_frame(bus, &ef, err_end);
      queue_frame(bus, &out, occupy(bus, &out, err_end));
      return;
    }
  }
  queue_frame(bus, &out, occupy(bus, &out, ready + E.delay));
}

static void send_due(double t) {
  int k = 0;
  while (k < E.nq) {
    if (E.q[k].due > t) {
      k++;
      continue;
    }
    struct can_frame c;
    memset(&c, 0, sizeof c);
    c.can_id = E.q[k].f.id;
    c.can_dlc = E.q[k].f.dlc;
    memcpy(c.data, E.q[k].f.data, 8);
    if (io.write(E.fd[E.q[k].bus], &c, sizeof c) == sizeof c) {
      E.n_tx++;
      E.frames_out[E.q[k].bus]++;
    }
    memmove(&E.q[k], &E.q[k + 1], sizeof E.q[0] * (size_t)(E.nq - k - 1));
    E.nq--;
  }
}

static double next_due(void) {
  double d = INFINITY;
  for (int k = 0; k < E.nq; k++)
    if (E.q[k].due < d) d = E.q[k].due;
  return d;
}

static void receive(int b, double t) {
  struct can_frame c;
  while (io.read(E.fd[b], &c, sizeof c) == sizeof c) {
    hcan_frame f = { .id = c.can_id, .dlc = c.can_dlc };
    memcpy(f.data, c.data, 8);
    E.n_rx++;
    E.frames_in[b]++;
    const double end = occupy(b, &f, t);   /* the host's frame on the wire */
    hcan_frame out[4];
    const int n = emu_handle(&E.w, b, &f, end, out);
    for (int k = 0; k < n; k++) enqueue(b, &out[k], end + PROCESS_TIME);
  }
}

/* ---------------------------------------------------------------- stdin and statistics */

static void stats(void) {
  for (int k = 0; k < E.w.n; k++) {
    const emu_board *b = &E.w.b[k];
    const ht_board *d = b->def;
    if (d->kind == HT_JMC)
      printf("board %s bus %d number 0x%02X ref %ld %ld enc %ld %ld fet %d ctrl %d home %d dead %d refs %u mode %d "
             "amps %.2f %.2f mode_frames %u cur_refs %u enc_reqs %u\n", d->name, d->bus + 1, d->number,
             lround(b->ref[0]), lround(b->ref[1]), lround(b->pos[0]), lround(b->pos[1]), b->fet, b->ctrl, b->home_state,
             b->dead, b->refs, b->mode, b->amps[0], b->amps[1], b->mode_frames, b->cur_refs, b->enc_reqs);
    else
      printf("%s %s bus %d number %d dead %d\n", d->kind == HT_JMC3 ? "silent" : "sensor", d->name, d->bus + 1,
             d->number, b->dead);
  }
  const double span = now() - E.t0;
  for (int b = 0; b < E.table.nbus; b++)
    printf("bus %d frames_in %llu frames_out %llu bits %llu load_pct %.1f\n", b + 1, (unsigned long long)E.frames_in[b],
           (unsigned long long)E.frames_out[b], (unsigned long long)E.bits[b],
           span > 0 ? 100.0 * E.bits[b] / (E.table.bitrate * span) : 0);
  printf("totals rx %lu tx %lu dropped %lu corrupted %lu overflow %lu unparsed %u\n", E.n_rx, E.n_tx, E.n_dropped,
         E.n_corrupted, E.n_overflow, E.w.unparsed);
  printf("end\n");
  fflush(stdout);
}

static void command(char *line) {
  char what[32] = "", name[64] = "";
  double v[4] = { 0, 0, 0, 0 };
  const int n = sscanf(line, "%31s %63s %lf %lf %lf", what, name, &v[0], &v[1], &v[2]);
  if (n < 1) return;
  emu_board *b = n >= 2 ? emu_find(&E.w, name) : NULL;
  if (!strcmp(what, "quit")) stop = 1;
  else if (!strcmp(what, "stats")) stats();
  else if (!strcmp(what, "dead") && b) b->dead = 1;
  else if (!strcmp(what, "alive") && b) b->dead = 0;
  else if (!strcmp(what, "error") && b && n >= 4) {
    b->faults = (uint8_t)v[0];
    b->limits = (uint8_t)v[1];
  } else if (!strcmp(what, "move") && b && n == 4 && v[0] >= 0 && v[0] < b->def->nch) {
    b->pos[(int)v[0]] = v[1];
  } else if (!strcmp(what, "ft") && b && n == 5) {
    memcpy(b->ft, v, sizeof b->ft);
  } else if (!strcmp(what, "imu") && sscanf(line, "%*s %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3]) == 4) {
    memcpy(E.w.imu, v, sizeof E.w.imu);
  } else if (!strcmp(what, "power") && sscanf(line, "%*s %lf %lf %lf", &v[0], &v[1], &v[2]) == 3) {
    memcpy(E.w.power, v, sizeof E.w.power);
  } else {
    fprintf(stderr, "hubo_emulator: unknown command or board: %s", line);
  }
}

static void read_stdin(void) {
  static char buf[4096];
  static size_t len;
  const ssize_t r = read(0, buf + len, sizeof buf - 1 - len);
  if (r <= 0) {
    if (r == 0) E.use_stdin = 0;   /* end of input: keep running */
    return;
  }
  len += (size_t)r;
  buf[len] = '\0';
  char *line = buf, *nl;
  while ((nl = strchr(line, '\n'))) {
    *nl = '\0';
    char cmd[512];
    snprintf(cmd, sizeof cmd, "%s\n", line);
    command(cmd);
    line = nl + 1;
  }
  len = strlen(line);
  memmove(buf, line, len + 1);
}

/* ---------------------------------------------------------------- main */

static void usage(void) {
  fprintf(stderr, "usage: hubo_emulator [--robot NAME] [--iface BUS=NAME]... [--unhomed] [--tau S] [--no-timing]\n"
                  "                     [--drop P] [--corrupt P] [--delay S] [--dead BOARD]... [--error BOARD]...\n"
                  "                     [--seed N] [--stdin] [--realtime] [--quiet] [--sim-id N]\n");
}

int main(int argc, char **argv) {
  const char *dead[HT_BOARD_MAX], *errb[HT_BOARD_MAX], *iface[HT_BUS_MAX] = { 0 };
  int ndead = 0, nerr = 0, homed = 1, realtime = 0, sim_id = 0;
  static emu_sim sim;
  double tau = 0.02;
  E.timing = 1;
  srand(1);
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "--unhomed")) { homed = 0; continue; }
    if (!strcmp(a, "--no-timing")) { E.timing = 0; continue; }
    if (!strcmp(a, "--stdin")) { E.use_stdin = 1; continue; }
    if (!strcmp(a, "--quiet")) { E.quiet = 1; continue; }
    if (!strcmp(a, "--realtime")) { realtime = 1; continue; }
    if (!v) { usage(); return 2; }
    if (!strcmp(a, "--robot")) setenv("ROBOT", v, 1);
    else if (!strcmp(a, "--iface")) {
      const int b = atoi(v);
      const char *eq = strchr(v, '=');
      if (!eq || b < 1 || b > HT_BUS_MAX) { usage(); return 2; }
      iface[b - 1] = eq + 1;
    } else if (!strcmp(a, "--tau")) tau = atof(v);
    else if (!strcmp(a, "--drop")) E.p_drop = atof(v);
    else if (!strcmp(a, "--corrupt")) E.p_corrupt = atof(v);
    else if (!strcmp(a, "--delay")) E.delay = atof(v);
    else if (!strcmp(a, "--dead") && ndead < HT_BOARD_MAX) dead[ndead++] = v;
    else if (!strcmp(a, "--error") && nerr < HT_BOARD_MAX) errb[nerr++] = v;
    else if (!strcmp(a, "--seed")) srand((unsigned)atoi(v));
    else if (!strcmp(a, "--sim-id")) sim_id = atoi(v);
    else { usage(); return 2; }
    i++;
  }
  if (!getenv("ROBOT") || !*getenv("ROBOT")) setenv("ROBOT", "hubo2plus", 1);
  const char *fake = getenv("HUBO_FAKE_CAN");
  if (fake && !strcmp(fake, "1")) io = fakecan_sys;
  char err[1024];
  dcm_config *rc = NULL, *cc = NULL, *ac = NULL;
  int r = dcm_config_load("robot", NULL, "Hubo", &rc, err, sizeof err);
  if (r == 0) r = dcm_config_load("can", dcm_config_robot(rc), "Hubo", &cc, err, sizeof err);
  if (r == 0) r = ht_load(rc, cc, &E.table, err, sizeof err);
  if (r == 0) r = dcm_config_load("actuators", dcm_config_robot(rc), "Hubo", &ac, err, sizeof err);
  if (r == 0) r = ht_load_actuators(rc, ac, &E.table, err, sizeof err);
  dcm_config_free(rc);
  dcm_config_free(cc);
  dcm_config_free(ac);
  if (r < 0) {
    fprintf(stderr, "hubo_emulator: %s\n", err);
    return 2;
  }
  emu_init(&E.w, &E.table, homed, tau);
  if (sim_id) {
    /* the physics has no homing: the boards start homed at the simulated pose */
    if (!homed || sim_id < 0) { usage(); return 2; }
    if (emu_sim_open(&sim, sim_id, err, sizeof err) < 0) {
      fprintf(stderr, "hubo_emulator: --sim-id %d: %s\n", sim_id, err);
      return 1;
    }
    emu_sim_step(&sim, &E.w);
  }
  for (int k = 0; k < ndead + nerr; k++) {
    const char *name = k < ndead ? dead[k] : errb[k - ndead];
    emu_board *b = emu_find(&E.w, name);
    if (!b) {
      fprintf(stderr, "hubo_emulator: no board '%s' in %s's can.lua\n", name, E.table.name);
      return 2;
    }
    if (k < ndead) b->dead = 1;
    else b->faults = 0x04;   /* big position error */
  }
  for (int b = 0; b < E.table.nbus; b++) {
    E.fd[b] = open_bus(iface[b] ? iface[b] : E.table.iface[b], err, sizeof err);
    if (E.fd[b] < 0) {
      fprintf(stderr, "hubo_emulator: bus %d: %s\n", b + 1, err);
      return 1;
    }
  }
  if (realtime) {
    struct sched_param sp = { .sched_priority = 30 };
    if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0 && !E.quiet)
      fprintf(stderr, "hubo_emulator: no real-time priority (%s)\n", strerror(errno));
  }
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  signal(SIGPIPE, SIG_IGN);
  fprintf(stderr, "hubo_emulator: ready (%s: %d boards on %d buses)\n", E.table.name, E.w.n, E.table.nbus);
  E.t0 = now();
  double last = E.t0;
  struct pollfd pf[HT_BUS_MAX + 1];
  while (!stop) {
    const int nb = E.table.nbus;
    for (int b = 0; b < nb; b++) pf[b] = (struct pollfd){ .fd = E.fd[b], .events = POLLIN };
    pf[nb] = (struct pollfd){ .fd = E.use_stdin ? 0 : -1, .events = POLLIN };
    double t = now();
    double wait = next_due() - t;
    if (wait > 0.005) wait = 0.005;   /* the joints move on between frames */
    if (wait < 0) wait = 0;
    struct timespec ts = { 0, (long)(wait * 1e9) };
    io.ppoll(pf, (nfds_t)nb + 1, &ts, NULL);
    t = now();
    if (sim_id) emu_sim_step(&sim, &E.w);
    else emu_step(&E.w, t, t - last);
    last = t;
    for (int b = 0; b < nb; b++)
      if (pf[b].revents & POLLIN) receive(b, t);
    if (pf[nb].revents & (POLLIN | POLLHUP)) read_stdin();
    send_due(now());
  }
  if (!E.quiet) stats();
  for (int b = 0; b < E.table.nbus; b++) io.close(E.fd[b]);
  if (sim_id) emu_sim_close(&sim);
  return 0;
}
