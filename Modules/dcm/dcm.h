/* dcm: the library every DCM is built on (Platforms/Sim, Platforms/OP, later Hubo).
 *
 * A DCM is a driver -- a table of functions in the lifecycle of ros2_control's hardware
 * interfaces: configure (parse config, no I/O), open (communication), enable (power, hold the
 * present pose), then write / read every cycle -- run by dcm_main, which does the rest the same way
 * for every platform:
 *   config    one strict reader: an embedded LuaJIT runs Lib/Config.lua's
 *             Config.export(concern, { robot =, platform = }); errors name the file(s) and the key
 *   blocks    dcm.sensor, dcm.actuator, dcm.stats and sync of every robot, bound through the structs
 *             generated from Config/shm.schema at build time (dcm_blocks.h): no field lists by hand
 *   pacing    absolute deadlines, missed cycles, jitter p50 / p99 / max and the rate, into dcm.stats
 *   guard     NaN / inf commands refused (counted), hardness clamped to 0..1, torques clamped to
 *             each joint's limit (a joint whose torque is refused held in position mode); the
 *             watchdog: when tick_ack stops advancing or its writer dies, every joint in position
 *             mode holding the present pose at the safe hardness until acknowledgements return
 *   lockstep  the DCM side of the sync block (Lib/lockstep.lua is the participants' side)
 *   args      the command line, from a table of each DCM's options (args.h)
 *
 * Errors: functions return 0 (or a count) on success and a negative errno code on failure with a
 * message in the caller's buffer. Nothing here calls exit() (a DCM must never die with the motors
 * on) but dcm_args, which runs before anything is opened. No hidden state except the signal flag
 * of dcm_main.
 */
#ifndef HRP_DCM_H
#define HRP_DCM_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "dcm_blocks.h"   /* generated from Config/shm.schema */
#include "shm/shm.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DCM_NJ_MAX 64        /* joints of one robot */
#define DCM_ROBOTS_MAX 16    /* robots served by one DCM (the sim's world) */
#define DCM_NAME_MAX 64      /* names in config (joints, models, robots) */
#define DCM_JITTER_MAX 4096  /* cycles of one statistics window */
#define DCM_SYNC_MAX 64      /* participant slots of a sync block looked at (the schema's nsync) */

/* ---------------------------------------------------------------- config */

typedef struct dcm_config dcm_config;   /* one concern, merged over its layers */

/* Loads `concern` ("robot", "dcm", "sim" ...) through $HRP_ROOT/Lib/Config.lua for robot and
 * platform (NULL: $ROBOT and $PLATFORM, defaulted as Config.lua does). */
int dcm_config_load(const char *concern, const char *robot, const char *platform, dcm_config **out, char *err,
                    size_t errlen);
void dcm_config_free(dcm_config *c);
/* The layer files the concern came from ("Config/robots/op3/robot.lua"; several joined by " + "). */
const char *dcm_config_files(const dcm_config *c);
/* The robot and platform it was loaded for. */
const char *dcm_config_robot(const dcm_config *c);
const char *dcm_config_platform(const dcm_config *c);
/* The project's root: $HRP_ROOT, else the source tree the library was built from. */
const char *dcm_root(void);

/* Keys are dotted paths; a number indexes a list from 1: "devices.3.model" (messages print it as
 * devices[3].model). Every getter fails with the files and the key named when the key is missing
 * or of another type. */
int dcm_config_has(const dcm_config *c, const char *key);
int dcm_config_num(const dcm_config *c, const char *key, double *out, char *err, size_t errlen);
/* A number that must be an integer. */
int dcm_config_int(const dcm_config *c, const char *key, int *out, char *err, size_t errlen);
int dcm_config_bool(const dcm_config *c, const char *key, int *out, char *err, size_t errlen);
int dcm_config_str(const dcm_config *c, const char *key, char *out, size_t outlen, char *err, size_t errlen);
/* Optional keys: *out = dflt when absent (a present key of another type is still an error). */
int dcm_config_num_or(const dcm_config *c, const char *key, double dflt, double *out, char *err, size_t errlen);
int dcm_config_str_or(const dcm_config *c, const char *key, const char *dflt, char *out, size_t outlen, char *err,
                      size_t errlen);
/* Entries of the list at key (the rows of a table such as devices); an error if not a list. */
int dcm_config_len(const dcm_config *c, const char *key, char *err, size_t errlen);
/* A list of min..max numbers / strings into out; returns how many. */
int dcm_config_nums(const dcm_config *c, const char *key, double *out, int min, int max, char *err, size_t errlen);
int dcm_config_strs(const dcm_config *c, const char *key, char (*out)[DCM_NAME_MAX], int min, int max, char *err,
                    size_t errlen);
/* The robot's joint order (the list `joints`, 1..DCM_NJ_MAX names) and each joint's limits (rad,
 * `limits.<joint>` = { min, max } with min below max) into lo and hi; returns the number of joints. */
int dcm_config_joints(const dcm_config *c, char (*joint)[DCM_NAME_MAX], double *lo, double *hi, char *err,
                      size_t errlen);
/* Writes "<files>: <message>" into err (for checks of the caller's own); returns -EINVAL. */
int dcm_config_fail(const dcm_config *c, char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* ---------------------------------------------------------------- blocks */

/* Opens (creating it if needed) block `block` of robot_id and binds a generated struct:
 *   dcm_blk_dcm_sensor s;  dcm_blocks_open(schema, id, DCM_BLK_dcm_sensor(&s), err, sizeof err);
 * then s.position[j], s.n.position. Fails naming the block and the field on a mismatch. */
int dcm_blocks_open(const shm_schema *schema, int robot_id, const char *block, const dcm_blk_field *fields,
                    int nfields, void *out, shm_block **blk, char *err, size_t errlen);
/* Binds a block that is already open. */
int dcm_blocks_bind(shm_block *b, const char *block, const dcm_blk_field *fields, int nfields, void *out,
                    shm_block **blk, char *err, size_t errlen);
/* A robot's dcm.sensor and dcm.actuator as a process beside its DCM sees them (an emulator serving a
 * simulated robot): loads the schema into *schema and binds both blocks; on failure nothing stays open. */
int dcm_robot_attach(int robot_id, shm_schema **schema, dcm_blk_dcm_sensor *sensor, dcm_blk_dcm_actuator *actuator,
                     char *err, size_t errlen);
/* Closes what dcm_robot_attach opened (any part of it; a second call does nothing). */
void dcm_robot_detach(shm_schema **schema, dcm_blk_dcm_sensor *sensor, dcm_blk_dcm_actuator *actuator);

/* ---------------------------------------------------------------- pacing */

/* A clock: monotonic seconds, and a sleep to an absolute time (tests give a fake one). */
typedef struct dcm_clock {
  double (*now)(void *ctx);
  void (*sleep_until)(void *ctx, double t);
  void *ctx;
} dcm_clock;

/* CLOCK_MONOTONIC; a sleep ends early once *stop (a signal's flag, may be NULL) is set. */
dcm_clock dcm_clock_wall(volatile sig_atomic_t *stop);

typedef struct dcm_pacer {
  dcm_clock clock;
  double period;                 /* s */
  double window;                 /* s of the clock per statistics window (1) */
  double deadline;               /* s, start of the current cycle as planned */
  uint32_t cycles, missed;       /* cycles run; cycles lost to overruns (skipped, not raced) */
  double rate;                   /* Hz over the last window */
  double jitter_p50, jitter_p99, jitter_max; /* s, |start - deadline| over the last window */
  int closed;                    /* 1 in the cycle that closed a window */
  uint32_t window_cycles;        /* cycles of the window just closed */
  /* private */
  double win_start;
  uint32_t win_cycles;
  int njit;
  double jit[DCM_JITTER_MAX];
} dcm_pacer;

void dcm_pacer_init(dcm_pacer *p, double period, dcm_clock clock);
/* Sleeps until the next deadline; returns the clock time. An overrun longer than a period counts
 * the lost cycles as missed and restarts the deadlines from now. */
double dcm_pacer_wait(dcm_pacer *p);
/* A cycle paced by someone else (lockstep): counted for the rate, no deadline, no jitter. */
double dcm_pacer_count(dcm_pacer *p);

/* ---------------------------------------------------------------- guard */

/* A joint's actuator mode (dcm.actuator.mode). */
enum { DCM_MODE_POSITION = 0, DCM_MODE_TORQUE = 1 };

/* One cycle's commands of a robot. */
typedef struct dcm_command {
  double position[DCM_NJ_MAX];   /* rad */
  double hardness[DCM_NJ_MAX];   /* 0..1, fraction of the servo's torque */
  int32_t enable[DCM_NJ_MAX];    /* 0 / 1 */
  int32_t mode[DCM_NJ_MAX];      /* DCM_MODE_POSITION: position and hardness; DCM_MODE_TORQUE: torque */
  double torque[DCM_NJ_MAX];     /* N*m, in torque mode */
  uint32_t tick_ack;             /* last sensor tick the motion process acted on */
  uint32_t writer_pid;
} dcm_command;

/* What /proc says of a process, for telling a stalled writer from a starved one. */
typedef struct dcm_proc {
  int state;                     /* the state letter of /proc/PID/stat ('R', 'S', 'T' ...); 0: no such process */
  unsigned long long start;      /* start time, clock ticks after boot (field 22): a reused pid has another */
  double cpu;                    /* s on a CPU, all threads (the process's CPU clock, ns resolution) */
} dcm_proc;

/* Probes pid into *out: 0, or -ESRCH (out->state = 0) when there is no such process. */
int dcm_proc_probe(int pid, dcm_proc *out);
/* Only its CPU time (one system call, cheap enough for every cycle); -1 when unknown. */
double dcm_proc_cpu(int pid);

/* The verdict on a writer that has not acknowledged for a while (dcm_writer_verdict). */
enum {
  DCM_WRITER_RUNS = 0,           /* running or runnable, not burning CPU: starved or blocked -- the timeout's case */
  DCM_WRITER_GONE,               /* no such process, a zombie, or its pid now belongs to another process */
  DCM_WRITER_STOPPED,            /* SIGSTOP / SIGTSTP, or stopped by a tracer */
  DCM_WRITER_BUSY                /* more than cpu_limit s of CPU since its last acknowledgement */
};
/* registered: the writer as first seen (its start time); at_ack: its CPU time at its last
 * acknowledgement; now: a probe of this cycle. */
int dcm_writer_verdict(const dcm_proc *registered, double cpu_at_ack, const dcm_proc *now, double cpu_limit);

/* A body's safe state (robot.lua `safe_pose`): on a trip each joint moves from where it is to q[j]
 * (rad; NaN: held where it is) within `ramp` s, smoothly. The joints with an angle are held at most at
 * `hardness` (NaN: the platform's safe_hardness, as every other joint is): a body whose motors cannot
 * carry it in its crouch at the platform's figure names a higher one. */
typedef struct {
  double q[DCM_NJ_MAX];
  double ramp, hardness;
} dcm_safe_pose;

typedef struct dcm_guard {
  int nj;
  double timeout;                /* s of the robot clock without a new tick_ack (<= 0: no watchdog) */
  int stall_cycles;              /* cycles without a new tick_ack before /proc is asked (<= 0: never) */
  double stall_cpu;              /* s of CPU the writer may burn without acknowledging (a busy loop beyond) */
  int (*probe)(int pid, dcm_proc *out);   /* dcm_proc_probe (tests give fake ones) */
  double (*cpu)(int pid);                 /* dcm_proc_cpu */
  int cause;                     /* the last trip's cause: DCM_WRITER_* (DCM_WRITER_RUNS: the timeout) */
  double safe_hardness;          /* 0..1, held in the safe state */
  int safe;                      /* 1 while holding the safe pose */
  uint32_t trips, refused;       /* watchdog trips; NaN / inf values refused */
  double torque_limit[DCM_NJ_MAX];   /* N*m per joint; 0: the platform has no torque path for it */
  uint32_t torque_refused;       /* torque-mode commands refused: the joint held in position mode */
  uint32_t torque_clamped;       /* torques clamped to their joint's limit */
  uint32_t trip_lag;             /* cycles since the writer's last tick_ack at the last trip */
  int dead_writer;               /* the last trip's cause: the writer's pid that died (0: the timeout) */
  /* private */
  uint32_t last_ack;
  double ack_time;
  int armed;                     /* a nonzero tick_ack was seen: somebody drives the robot */
  int watch_pid, watch_fd;       /* the writer watched, its pidfd (-1: none) */
  dcm_proc registered;           /* the watched writer when first seen (state 0: unknown) */
  int still;                     /* cycles since tick_ack last moved */
  double cpu_at_ack;             /* the writer's CPU time when tick_ack last moved (< 0: unknown) */
  dcm_safe_pose pose;            /* where the safe state moves the joints, how fast, how hard */
  double trip_time;              /* robot time of the trip */
  double last_pos[DCM_NJ_MAX], last_hard[DCM_NJ_MAX], hold[DCM_NJ_MAX];
  int32_t held[DCM_NJ_MAX];      /* 1 while a refused torque-mode joint is held at torque_hold */
  double torque_hold[DCM_NJ_MAX];
} dcm_guard;

/* present: the pose held until the first commands (nj rad). */
void dcm_guard_init(dcm_guard *g, int nj, double timeout, double safe_hardness, const double *present,
                    uint32_t tick_ack);
/* The safe state's pose (NULL: every joint held where it is at the safe hardness, the default). */
void dcm_guard_set_safe_pose(dcm_guard *g, const dcm_safe_pose *pose);
/* The safe pose of body `robot` (its robot.lua, the Config layers of $PLATFORM): `safe_pose = { ramp = s,
 * [hardness = 0..1,] q = { joint = rad, ... } }`; a joint not named (or no safe_pose at all) is NaN:
 * held where it is. Returns the number of joints with an angle, or < 0 (err names file and key). */
int dcm_safe_pose_load(const char *robot, int nj, dcm_safe_pose *out, char *err, size_t errlen);
/* Each joint's torque limit (nj N*m, the platform's actuator data; NULL or 0: no torque mode for the
 * joint, which then stays in position mode). Until this is called no joint has a torque path. */
void dcm_guard_set_torque_limits(dcm_guard *g, const double *limit);
/* The stall check (Config: stall_cycles, stall_cpu): after `cycles` guard cycles without a new
 * tick_ack the writer is looked at -- stopped, gone (or its pid reused) or more than `cpu` s of CPU
 * burnt since its last tick_ack trips at once; a writer that merely did not run is left to the
 * timeout. Runs in lockstep too, where the timeout does not. */
void dcm_guard_set_stall(dcm_guard *g, int cycles, double cpu);
/* Copies a robot's commands out of dcm.actuator (a torn read is retried). */
void dcm_command_read(const dcm_blk_dcm_actuator *a, int nj, dcm_command *out);
/* Checks commands in place at robot time `now`: NaN / inf -> the last good value (counted),
 * hardness clamped; a joint in torque mode has its torque clamped to its limit (counted), and a NaN
 * / inf torque, a mode other than position or torque, or a joint without a torque limit is refused
 * (counted): the joint goes to position mode holding `present` as it was at the refusal, until a
 * valid command comes. On a watchdog trip every joint goes to position mode: it holds `present`
 * (the sensed pose, rad), or moves from it into the safe pose, at the safe hardness until tick_ack
 * moves again. Returns 1 while in the safe state. */
int dcm_guard_apply(dcm_guard *g, double now, const double *present, dcm_command *c);
/* A trip's end of torque mode in the block itself: every joint of `a` in torque mode is put in
 * position mode with its command at hold[j] (the pose of the trip) and its torque 0, so the robot's
 * processes find it there when they answer again (a stale torque never resumes by itself). */
void dcm_actuator_position_mode(const dcm_blk_dcm_actuator *a, int nj, const double *hold);

/* ---------------------------------------------------------------- lockstep */

typedef struct dcm_lockstep {
  int n;                                /* robots, each with its sync block */
  dcm_blk_sync *sync[DCM_ROBOTS_MAX];
  double spin;                          /* s of polling before sleeping on the futex */
  double drop_after;                    /* s of waiting before dead participants are dropped */
  uint32_t dropped;                     /* participants dropped because they died */
  int start_with;                       /* participants to wait for before the first tick (<= 1: one) */
  int started;                          /* the clock has run (set by dcm_lockstep_wait) */
  double stall_after;                   /* s of waiting before a pending participant is looked at: a
                                           stopped one is passed over while it stays stopped (<= 0: never) */
  uint32_t passed;                      /* times a stopped participant was passed over */
  int (*probe)(int pid, dcm_proc *out); /* NULL: dcm_proc_probe */
  /* private: the pid of each slot passed over (0: none) */
  int32_t skip[DCM_ROBOTS_MAX][DCM_SYNC_MAX];
} dcm_lockstep;

/* Lockstep on: participants registered with an earlier DCM are consulted from `tick` on. */
void dcm_lockstep_start(dcm_lockstep *l, uint32_t tick);
/* Before the first tick is published: until start_with participants have joined (idle runs
 * meanwhile), so that all of them begin on that tick, each in its stage (Lib/lockstep.lua: the
 * behavior after motion, which it would not wait for if motion had not joined yet). Returns 0, or 1
 * when *stop was set. */
int dcm_lockstep_hold(dcm_lockstep *l, uint32_t tick, void (*idle)(void *ctx, int alone), void *ctx,
                      volatile sig_atomic_t *stop);
/* Tick `tick` is published (dcm.sensor written): participants may work on it. */
void dcm_lockstep_publish(dcm_lockstep *l, uint32_t tick);
/* Waits until every live participant whose wake_tick <= tick reports done_tick >= tick (one found
 * stopped after stall_after s is passed over, and from then on while it stays stopped); while
 * nobody has joined at all, holds the clock (before its first tick: until start_with have joined,
 * so that a run whose participants start at different moments still starts on a defined tick). idle(ctx, alone) runs while waiting. Returns 0, or 1
 * when *stop was set. */
int dcm_lockstep_wait(dcm_lockstep *l, uint32_t tick, void (*idle)(void *ctx, int alone), void *ctx,
                      volatile sig_atomic_t *stop);
/* Lockstep off (also for a real-time DCM at start, so no participant waits for it). */
void dcm_lockstep_end(dcm_lockstep *l);

/* ---------------------------------------------------------------- lifecycle */

/* One robot served by the DCM. */
typedef struct dcm_robot {
  int id;                         /* ROBOT_ID of its blocks */
  int nj;                         /* its joints: the first nj entries of every joint array */
  char name[DCM_NAME_MAX];        /* its body (ROBOT) */
  dcm_blk_dcm_sensor sensor;
  dcm_blk_dcm_actuator actuator;
  dcm_blk_dcm_stats stats;
  dcm_blk_sync sync;
  dcm_guard guard;
  dcm_command cmd;                /* this cycle's commands, after the guard */
  double torque_limit[DCM_NJ_MAX];   /* N*m per joint, set by the driver's configure: its torque path's
                                        limit (0, the default: no torque mode for the joint) */
} dcm_robot;

typedef struct dcm {
  const char *name;               /* program name, prefix of messages */
  /* filled by the driver's configure */
  int nrobots;
  dcm_robot robot[DCM_ROBOTS_MAX];
  double period;                  /* s, control period */
  double watchdog;                /* s without a new tick_ack before the safe state (<= 0: none) */
  int stall_cycles;               /* cycles without a new tick_ack before the writer is probed (<= 0: never) */
  double stall_cpu;               /* s of CPU the writer may burn without a tick_ack */
  double safe_hardness;           /* 0..1 */
  double start_hardness;          /* 0..1, every joint's hardness at start (present pose, torque on) */
  int simulated;                  /* 1: the robot clock is tick * period (simulation) */
  /* options (command line) */
  int lockstep;                   /* wait each tick for the sync participants */
  long max_cycles;                /* stop after this many cycles (< 0: run until a signal) */
  int quiet;
  /* state, read by drivers */
  uint32_t tick;                  /* last published tick */
  double time;                    /* s, robot clock of the last published tick */
  double now;                     /* s, wall clock at the start of this cycle */
  dcm_pacer pacer;
  dcm_lockstep sync;
  shm_schema *schema;
  volatile sig_atomic_t *stop;    /* set by SIGINT / SIGTERM or dcm_stop */
  /* private */
  double t0, time0;
} dcm;

typedef struct dcm_driver {
  /* Parses config into hw and fills nrobots, robot[].id / nj / name, period, watchdog,
   * safe_hardness, start_hardness, simulated. No I/O. */
  int (*configure)(void *hw, dcm *d, char *err, size_t errlen);
  /* Opens communication. -EAGAIN: not there yet, retried every 0.5 s until it works. */
  int (*open)(void *hw, dcm *d, char *err, size_t errlen);
  /* Powers on and holds; afterwards publish gives the present pose. */
  int (*enable)(void *hw, dcm *d, char *err, size_t errlen);
  /* This cycle's commands (robot[r].cmd, checked by the guard) to the hardware. */
  void (*write)(void *hw, dcm *d);
  /* The hardware's state into the driver (the sim steps its world here). */
  void (*read)(void *hw, dcm *d);
  /* Robot r's sensors into dcm.sensor, inside its write lock (time, tick, period, dcm_pid are set). */
  void (*publish)(void *hw, dcm *d, int r, const dcm_blk_dcm_sensor *s);
  /* Optional: the platform's figures into dcm.stats, inside its write lock. */
  void (*stats)(void *hw, dcm *d, int r, const dcm_blk_dcm_stats *s);
  /* Optional: runs while lockstep waits for participants (alone: nobody has joined yet). */
  void (*idle)(void *hw, dcm *d, int alone);
  /* Optional: the tick is published; runs before the wait for the next cycle. */
  void (*published)(void *hw, dcm *d);
  /* Optional: last call (the servos keep holding where they are). */
  void (*close)(void *hw, dcm *d);
} dcm_driver;

/* Runs a DCM: configure, blocks, open (retried), enable, then cycles until a signal, dcm_stop or
 * max_cycles. Returns 0, -EINVAL for bad configuration (the message names file and key), or
 * another negative code. */
int dcm_main(dcm *d, const dcm_driver *drv, void *hw, char *err, size_t errlen);
/* dcm_main for a DCM's main(): its error printed as "<name>: <message>" on stderr. Returns the
 * process's exit status: 0, 2 for -EINVAL (the configuration or the arguments), 1 for any other
 * failure. */
int dcm_run(dcm *d, const dcm_driver *drv, void *hw);
/* Asks dcm_main to finish the current cycle and return. */
void dcm_stop(dcm *d);
/* "<name>: message" on stderr, unless quiet. */
void dcm_log(const dcm *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#ifdef __cplusplus
}
#endif
#endif
