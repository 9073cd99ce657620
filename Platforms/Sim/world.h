// world: the ODE world of the sim DCM -- field, goals, ball and any number of robots built from a
// Model; position servos, IMU, foot forces, truth, teleports and pushes. No shared memory here:
// Platforms/Sim/dcm_sim.cpp connects it to the blocks, so tests can drive it directly.
//
// Determinism: the world does the same floating-point work for the same seed and the same calls.
#ifndef HRP_SIM_WORLD_H
#define HRP_SIM_WORLD_H

#include <ode/ode.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "config.h"
#include "effects.h"
#include "model.h"

namespace sim {

// A joint's servo: the numbers of its actuator model (Config/common/actuators.lua) that the URDF
// cannot carry (its torque, speed, damping and friction are the URDF joint's).
struct Servo {
  std::string model;            // e.g. "MX-28"
  double gain = 30;             // 1/s, velocity-motor gain: target speed = gain * position error
  double resolution = 4096;     // encoder counts per turn (positions are quantised to it)
  double speed_unit = 0.0240;   // rad/s per count of the present speed (speeds are quantised to it)
};

// Point pressure sensors under one foot (robot.lua `foot_pressure`, Platforms/Sim/pressure.h): the
// frame of the description whose x-y plane is the sole, and the sensors' positions in it.
struct PressureFoot {
  std::string frame;           // e.g. "l_sole"; its link is the foot whose ground contacts load them
  std::vector<double> xy;      // x0 y0 x1 y1 ... (m)
};

// Every number the world needs, from the sim, robot, camera and actuators configs (Lib/Config.lua layers).
struct Params {
  double timestep = 0.001, period = 0.008, gravity = 9.81;
  int iterations = 20;
  double rotor_inertia = 5e-4, linear_damping = 0;
  double gear_presliding = 2.9e-4;   // rad: a stuck gear's give before it slips (torque mode)
  double temperature = 40;
  double mu = 1, kp = 5e4, kd = 300, robot_mu = 0.5;
  int max_contacts = 8;
  double gyro_noise = 0, accel_noise = 0;
  double field_length = 9, field_width = 6, border = 1, line_width = 0.05, circle_diameter = 1.5;
  double goal_area_length = 1, goal_area_width = 3, penalty_area_length = 2, penalty_area_width = 5;
  double penalty_mark_distance = 1.5, penalty_mark_size = 0.1;
  double goal_width = 2.6, goal_height = 1.2, goal_depth = 0.6, post_diameter = 0.1;
  double ball_diameter = 0.14, ball_mass = 0.2, ball_mu = 0.6, ball_rolling = 0.004, ball_bounce = 0.5;
  double ball_start[2] = {0, 0};
  std::string ball_kind = "orange";   // sim.lua ball.kind: 'orange' (plain) or 'white' (patterned)
  // sim.lua teams: the jersey colour (Y, U, V) of team 1 and team 2, rendered on each robot's torso,
  // and each robot's team (index in the world's robot order; robots beyond the list: the first half
  // of the world's robots team 1, the rest team 2)
  unsigned char team_yuv[2][3] = {{83, 107, 212}, {72, 195, 98}};
  std::vector<int> robot_team;
  std::string camera_frame = "camera_link";
  int cam_width = 640, cam_height = 480;
  double cam_rate = 30, cam_fovy = 43.3 * M_PI / 180;
  int cam_latency_ticks = 3;
  double cam_noise = 2;
  // the camera's calibration (camera.lua intrinsics, distortion; OpenCV's convention, effects.h Lens)
  double cam_fx = 0, cam_fy = 0, cam_cx = 0, cam_cy = 0, cam_k1 = 0, cam_k2 = 0;
  Realism realism;                    // sim.lua camera: the camera's imperfections
  std::vector<double> start;   // x, y, yaw per robot, flattened
  // static boxes on the carpet (sim.lua `objects`: a step, a ramp): centre (field frame, m), size
  // (m), roll pitch yaw (rad); they collide as the carpet does and the camera sees them
  struct Object { double pos[3], size[3], rpy[3]; };
  std::vector<Object> objects;
  double fall_angle = 1.0, watchdog = 0.5, battery = 12;
  int stall_cycles = 2;                 // the DCM's stall check (sim.lua: stall_cycles, stall_cpu)
  double stall_cpu = 0.003;
  double safe_hardness = 0.3, start_hardness = 1;   // the DCM's safe state; every joint at start
  std::string name;                   // the body (robot.lua's name)
  std::vector<std::string> joints;    // shm joint order (robot.lua)
  // robot.lua's groups lleg, rleg, head (empty when the body has none): the sim's stance and tests
  std::vector<std::string> lleg, rleg, head;
  std::vector<Servo> servos;          // per shm joint: its actuator model (robot.lua `actuator`)
  // robot.lua's optional `ft`: per slot of dcm.sensor.ft (left foot, right foot, left hand, right
  // hand) the joint whose child link carries a 6-axis sensor, "" for none
  std::vector<std::string> ft = std::vector<std::string>(4);
  // robot.lua's optional `foot_pressure`: the left foot's sensors, then the right's (empty: none)
  std::vector<PressureFoot> pressure;
  std::string urdf;                   // path of the robot file
};
// Reads the sim, robot and camera configs of a body ("" = $ROBOT) into p; throws
// std::runtime_error naming the files and the key.
void params_load(const std::string &robot, Params *p);

// What the DCM publishes in dcm.sensor for one robot.
struct Sensors {
  std::vector<double> position, velocity, load;   // per shm joint
  double gyro[3], accel[3], angle[3], foot_force[2];
  // 6-axis sensors (slots as Params::ft): fx fy fz (N) mx my mz (N m) each, 0 where the body has
  // none. The wrench the sensor's link (and what it touches) exerts on the link above it, at the
  // joint's anchor, in the sensor link's frame: standing, a foot's fz carries the weight above it.
  double ft[24];
  // point pressure sensors (Params::pressure): N each, the left foot's then the right's, in the
  // order robot.lua lists them; the mean over the tick's physics steps; empty when the body has none
  std::vector<double> pressure;
};

// Field-frame truth of one robot's torso (body link frame) and the ball.
struct Truth {
  double x, y, z, yaw, roll, pitch;
  bool fallen;
  double ball[5];     // x, y, z, vx, vy
  // the centre of pressure of the ground's forces on the robot's feet (its soles' contacts and those
  // of the feet with pressure sensors, with the carpet and the static objects; their mean over the
  // tick): x, y where their moment has no horizontal part on the carpet's plane (z = 0), and their
  // vertical sum fz (N); 0 0 0 with no foot on the ground
  double cop[3];
};

// A convex solid for the camera: vertices (world) and faces (vertex index loops, outward CCW).
struct Solid {
  std::vector<Vec3> v;
  std::vector<std::vector<int>> faces;
  unsigned char yuv[3];
  int robot = -1, link = -1;        // owner, for hiding the camera's own head
};

// What the camera sees that moves, copied at the exposure tick: the link poses of every robot and
// the ball. Cheap to take on the physics thread; the solids are built from it on the render thread.
struct Scene {
  std::vector<Vec3> link_pos;   // robot r, link i at [first[r] + i] (link frame origin, field frame)
  std::vector<Mat3> link_rot;
  std::vector<size_t> first;
  Vec3 ball = Vec3::Zero();
  Mat3 ball_rot = Mat3::Identity();
};

// One robot's body: its description, the shm order of its joints (robot.lua's joints) and each
// joint's servo (its actuator model).
struct Body {
  Model model;
  std::vector<std::string> joints;
  std::vector<Servo> servos;   // per shm joint
  std::vector<std::string> ft = std::vector<std::string>(4);   // as Params::ft
  std::vector<PressureFoot> pressure;                          // as Params::pressure
};

class World {
 public:
  // nrobots robots of one body (joints: p.joints, servos: p.servos).
  World(const Params &p, const Model &m, int nrobots, uint64_t seed);
  // Robot r has bodies[r]: different bodies in one world. The world's own numbers come from p.
  World(const Params &p, std::vector<Body> bodies, uint64_t seed);
  ~World();
  World(const World &) = delete;
  World &operator=(const World &) = delete;

  int nrobots() const { return (int)robots_.size(); }
  int njoints(int r = 0) const { return (int)robots_[r].jlink.size(); }
  double time() const { return time_; }
  const Params &params() const { return p_; }
  const Model &model(int r = 0) const { return *robots_[r].m; }

  // Servo commands of robot r (arrays of njoints; rad, 0..1, 0/1) and, optionally, each joint's
  // actuator mode (0 position, 1 torque) and torque (N*m, for a joint in torque mode: applied through
  // its actuator model, world_step.cpp). Non-finite entries are ignored (the previous value stays)
  // and counted; returns how many were ignored.
  int set_command(int r, const double *cmd, const double *hardness, const int *enable, const int *mode = nullptr,
                  const double *torque = nullptr);
  const std::vector<double> &command(int r) const { return robots_[r].cmd; }
  // Advances one control period (period / timestep physics steps).
  void step();
  void sense(int r, Sensors *s);
  Truth truth(int r) const;
  // Places robot r at (x, y, yaw) on the carpet, its lower sole laid flat (a body without soles:
  // its torso upright), joints at `q` (njoints, NULL: its current commands), at rest.
  void place_robot(int r, double x, double y, double yaw, const double *q = nullptr);
  void place_ball(double x, double y, double vx = 0, double vy = 0);
  // Hangs robot r on a gantry: its torso (root link) lifted `height` m and held fixed to the world
  // (tests of the body against its rigid-body model, feet off the carpet); release_robot lets it go.
  void hang_robot(int r, double height);
  void release_robot(int r);
  // Robots to their start poses (current commands), ball to its start, score to 0:0.
  void reset();
  // A force (N, field frame, horizontal) on robot r's torso for `duration` s.
  void push(int r, double fx, double fy, double duration);
  // A force (N, field frame) at the origin of a link or frame of robot r (its URDF's name: 'r_palm')
  // for `duration` s; false if the body has no such link or frame.
  bool push_link(int r, const std::string &name, double fx, double fy, double fz, double duration);
  int score(int goal) const { return score_[goal]; }   // 0: goals into +x, 1: into -x
  // The robot whose body touched the ball last (a contact in the physics), -1: none since the ball
  // was placed; and the sim time of that touch. The referee's "last touched" (own goals, throw-ins).
  int ball_touch() const { return ball_touch_; }
  double ball_touch_time() const { return ball_touch_time_; }

  // Camera of robot r: world pose (columns of rot: optical axis, image-left, image-up).
  void camera_pose(int r, Vec3 *pos, Mat3 *rot) const;
  Vec3 ball_position() const;
  Mat3 ball_rotation() const;
  // The team (1 or 2) of robot r: its jersey colour (Params::robot_team, team_yuv).
  int team(int r) const;
  double ball_radius() const { return p_.ball_diameter / 2; }
  // Every solid the camera can see (goals; all robots' boxes), at their current poses.
  void solids(std::vector<Solid> *out) const;
  // The same from a snapshot: reads only what never changes after construction (the model and the
  // goals), so a render thread may call it while the physics steps.
  void snapshot(Scene *s) const;
  void solids(const Scene &s, std::vector<Solid> *out) const;
  // Joint positions of robot r in shm order (exact, not quantised).
  std::vector<double> joint_positions(int r) const;
  // Field-frame pose of a link of robot r.
  void link_pose(int r, int link, Vec3 *pos, Mat3 *rot) const;
  // Field-frame pose of a link or frame of robot r's description, by name (a frame, a massless
  // fixed child, rides on its link: the link's pose times the frame's offset). False if the body
  // has no link or frame of that name (pos and rot untouched).
  bool frame_pose(int r, const std::string &name, Vec3 *pos, Mat3 *rot) const;

 private:
  void release();   // the ODE world, spaces, joints and geometry infos (destructor, failed construction)
  struct GeomInfo { int kind; int robot; int link; int sole; };   // kind: 0 ground/env, 1 ball, 2 robot
  struct Robot {
    const Model *m = nullptr;              // its body (in bodies_)
    const std::vector<Servo> *servo = nullptr;   // its body's servos, per shm joint
    dSpaceID space = nullptr;
    dJointID gantry = nullptr;             // hang_robot's fixed joint to the world
    std::vector<dBodyID> body;             // per model link
    std::vector<dJointID> hinge;           // per model link (null for the root)
    std::vector<dJointFeedback> fb;        // per model link
    std::vector<int> jlink;                // shm joint -> model link
    std::vector<double> cmd, hard;
    std::vector<int> enable;
    std::vector<int> mode;                 // servo mode last set: 0 unset, 1 active, 2 relaxed, 3 torque
    std::vector<int> actuate;              // per shm joint: 0 position, 1 torque (as dcm.actuator.mode)
    std::vector<double> tau;               // per shm joint: the torque commanded (N*m)
    std::vector<double> applied;           // per shm joint: the torque applied in the last physics step
    std::vector<double> stick;             // per shm joint in torque mode: the angle its gear holds (rad)
    std::vector<char> allowed;             // self-collision allowed, nlink x nlink
    double foot_acc[2] = {0, 0};
    Vec3 vel_start = Vec3::Zero();
    Vec3 push_force = Vec3::Zero();
    double push_left = 0;
    int push_at = -1;                      // push_link's link (model index), -1: none
    Vec3 push_at_offset = Vec3::Zero();    // the point in that link's frame
    Vec3 push_at_force = Vec3::Zero();
    double push_at_left = 0;
    double accel[3] = {0, 0, 9.81};
    int ft_link[4] = {-1, -1, -1, -1};     // per ft slot: the sensor's (child) link, -1 none
    // pressure sensors per foot (left, right): the frame they sit in, its link (-1: none), and the
    // ground's force and moment (about the field's origin) on that link, summed over the tick's steps
    int press_frame[2] = {-1, -1}, press_link[2] = {-1, -1};
    const std::vector<PressureFoot> *pressure = nullptr;   // its body's sensors' layout
    Vec3 press_f[2] = {Vec3::Zero(), Vec3::Zero()}, press_m[2] = {Vec3::Zero(), Vec3::Zero()};
    // the same for every contact of its feet with the ground (Truth::cop)
    Vec3 ground_f = Vec3::Zero(), ground_m = Vec3::Zero();
  };
  // a contact of a robot with the ground, its force wanted after the step: robot, sole side (-1:
  // none), pressure foot (-1: none), whether the robot is body 1 (0) or 2 (1) of the contact joint,
  // the contact point
  struct ContactUse { int robot, sole, press, which; Vec3 pos; };

  void build_env();
  void build_robot(int r, const Body &body);
  void servo_update(Robot &rb);
  void physics_step();
  void set_hinge_feedback(bool on);
  void sense_ft(const Robot &rb, double *ft) const;   // world_ft.cpp
  static void near_cb(void *data, dGeomID o1, dGeomID o2);
  void collide(dGeomID o1, dGeomID o2);
  void check_goal();
  Vec3 body_pos(dBodyID b) const;
  Mat3 body_rot(dBodyID b) const;

  Params p_;
  std::vector<Body> bodies_;               // per robot
  dWorldID world_ = nullptr;
  dSpaceID top_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  dBodyID ball_ = nullptr;
  dGeomID ball_geom_ = nullptr;
  std::vector<GeomInfo *> infos_;
  std::vector<Robot> robots_;
  std::vector<Solid> goal_solids_;   // the static solids the camera sees: goals, objects
  std::vector<dJointFeedback> cfb_;        // contact feedback of sole contacts, this step
  std::vector<ContactUse> cfb_owner_;      // per cfb_ entry
  double time_ = 0;
  int substeps_ = 8;
  int score_[2] = {0, 0};
  int ball_touch_ = -1;
  double ball_touch_time_ = 0;
  int in_goal_ = 0;                         // latched: +1 / -1 while the ball is inside a goal
  uint64_t seed_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};


// The project's root: $HRP_ROOT, else the source tree the binary was built from.
std::string hrp_root();
// Config/robots/<robot> under the root.
std::string robot_dir(const std::string &robot);
// Params from <root>/Config/<platform>/{sim,robot}.lua ($PLATFORM, default Sim) and the model from
// the robot file they name. Throws std::runtime_error naming the file and the element or key.
// ball_kind: the ball the camera sees ("white", "orange"; "": the config's ball.kind).
void load_all(Params *p, Model *m, const std::string &ball_kind = "");
// Different bodies in one world: robots[r] names robot r's body ("" = $ROBOT); (*params)[r] are its
// numbers (robot.lua, camera.lua and sim.lua with its layers), (*bodies)[r] its description. The
// world's own numbers (physics, field, ball) are robot 0's. Throws naming the file and the key.
void load_bodies(const std::vector<std::string> &robots, std::vector<Params> *params, std::vector<Body> *bodies);
}  // namespace sim
#endif
