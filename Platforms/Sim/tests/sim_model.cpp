// sim_model: the robot file and the sim config (TAP): the OP3 URDF matches the reference's mass
// model; a missing or invalid robot file, or a broken config, fails with the file and element named.
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "world.h"
#include "tap.h"

static bool contains(const std::string &s, const std::string &part) { return s.find(part) != std::string::npos; }

static std::string load_err(const std::string &path, const std::string &text) {
  std::ofstream(path) << text;
  sim::Model m;
  std::string err;
  int rc = sim::model_load(path, &m, &err);
  unlink(path.c_str());
  return rc < 0 ? err : "";
}

int main() {
  sim::Params p;
  sim::Model m;
  try {
    sim::load_all(&p, &m);
  } catch (const std::exception &e) {
    printf("not ok 1 - loads the sim and robot configs: %s\n", e.what());
    return 1;
  }
  check(true, "loads the sim and robot configs and the URDF they name");
  printf("# %zu links, %zu frames, total mass %.4f kg\n", m.links.size(), m.frames.size(), m.total_mass());
  check(std::fabs(m.total_mass() - 3.1475) < 1e-3, "total mass is the reference's 3.1475 kg");
  // whole-body COM at the zero pose (reference: -0.0105675 7.17532e-05 0.274312 with soles on z=0)
  {
    sim::World w(p, m, 1, 1);
    std::vector<double> z(p.joints.size(), 0.0);
    w.place_robot(0, 0, 0, 0, z.data());
    sim::Vec3 com = sim::Vec3::Zero();
    double zmin = 1e9;
    for (size_t i = 0; i < m.links.size(); i++) {
      sim::Vec3 lp;
      sim::Mat3 R;
      w.link_pose(0, (int)i, &lp, &R);
      com += m.links[i].mass * (lp + R * m.links[i].com);
      for (const sim::Box &b : m.links[i].boxes) {
        if (b.sole) zmin = std::min(zmin, (lp + R * b.pos).z() - b.size.z() / 2);
      }
    }
    com /= m.total_mass();
    com.z() -= zmin;
    printf("# COM at the zero pose above the soles: %.5f %.5f %.5f\n", com.x(), com.y(), com.z());
    check((com - sim::Vec3(-0.0105675, 7.17532e-05, 0.274312)).norm() < 1e-4,
          "zero-pose COM matches the reference");
  }
  int cam = m.frame_index("camera_link");
  check(cam >= 0 && m.links[m.frames[cam].link].name == "head_tilt_link", "camera frame on head_tilt_link");

  const std::string dir = "/tmp/sim_model_test_" + std::to_string(getpid());
  std::string e;
  sim::Model x;
  const int rc = sim::model_load(dir + "_missing.urdf", &x, &e);
  check(rc < 0 && contains(e, "_missing.urdf"), "missing robot file: error names the file (" + e + ")");
  e = load_err(dir + "_a.urdf", "<robot name='x'><link name='a'>");
  check(contains(e, "_a.urdf") && contains(e, "invalid URDF"), "malformed XML: error names the file (" + e + ")");
  e = load_err(dir + "_b.urdf",
               "<robot name='x'><link name='base'><inertial><mass value='1'/><inertia ixx='1' iyy='1' izz='1' "
               "ixy='0' ixz='0' iyz='0'/></inertial></link><link name='leg'/><joint name='hip' "
               "type='revolute'><parent link='base'/><child link='leg'/><axis xyz='0 1 0'/><limit lower='-1' "
               "upper='1' effort='5' velocity='5'/></joint></robot>");
  check(contains(e, "_b.urdf") && contains(e, "link 'leg'") && contains(e, "<inertial>"),
        "link without inertial: error names file and link (" + e + ")");
  e = load_err(dir + "_c.urdf",
               "<robot name='x'><link name='base'><inertial><mass value='1'/><inertia ixx='1' iyy='1' izz='1' "
               "ixy='0' ixz='0' iyz='0'/></inertial><collision name='c'><geometry><sphere radius='1'/>"
               "</geometry></collision></link></robot>");
  check(contains(e, "link 'base'") && contains(e, "<collision c>"), "unsupported geometry named (" + e + ")");
  e = load_err(dir + "_d.urdf",
               "<robot name='x'><link name='base'><inertial><mass value='1'/><inertia ixx='1' iyy='1' izz='1' "
               "ixy='0' ixz='0' iyz='0'/></inertial></link><link name='leg'><inertial><mass value='1'/>"
               "<inertia ixx='1' iyy='1' izz='1' ixy='0' ixz='0' iyz='0'/></inertial></link><joint name='hip' "
               "type='revolute'><parent link='base'/><child link='leg'/><axis xyz='0 1 0'/><limit lower='1' "
               "upper='-1' effort='5' velocity='5'/></joint></robot>");
  check(contains(e, "joint 'hip'") && contains(e, "<limit>"), "bad joint limits named (" + e + ")");
  // a robot file without a joint the robot config lists
  {
    sim::Model small;
    std::string path = dir + "_e.urdf";
    std::ofstream(path) << "<robot name='x'><link name='base_link'><inertial><mass value='1'/><inertia ixx='1' "
                           "iyy='1' izz='1' ixy='0' ixz='0' iyz='0'/></inertial></link><link name='camera_link'/>"
                           "<joint name='cj' type='fixed'><parent link='base_link'/><child link='camera_link'/>"
                           "</joint></robot>";
    std::string err;
    sim::model_load(path, &small, &err);
    unlink(path.c_str());
    try {
      sim::World w(p, small, 1, 1);
      check(false, "a joint missing from the robot file is an error");
    } catch (const std::exception &ex) {
      check(contains(ex.what(), "_e.urdf") && contains(ex.what(), "no joint 'head_pan'"),
            std::string("a joint missing from the robot file is named: ") + ex.what());
    }
  }
  // config errors name the file and the key
  {
    // a site overlay (HRP_SITE) with a wrong type
    std::string site = dir + "_site";
    mkdir(site.c_str(), 0700);
    std::string path = site + "/sim.lua";
    std::ofstream(path) << "return { physics = { timestep = 'fast' } }";
    setenv("HRP_SITE", site.c_str(), 1);
    try {
      sim::Params q;
      sim::params_load("", &q);
      check(false, "config with a wrong type is an error");
    } catch (const std::exception &ex) {
      check(contains(ex.what(), "_site/sim.lua") && contains(ex.what(), "physics.timestep"),
            std::string("config error names file and key: ") + ex.what());
    }
    unsetenv("HRP_SITE");
    unlink(path.c_str());
    rmdir(site.c_str());
  }
  return tap_done();
}
