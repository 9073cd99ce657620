// world_solids: what the camera sees of the world -- the goals' posts and bars and the objects
// (static, built once), the robots' boxes in their team's colours (from a snapshot of the link
// poses, so that a render thread can build them while the physics steps).
#include <cmath>

#include "world_internal.h"

namespace sim {

namespace world_internal {

void box_solid(const Vec3 &c, const Mat3 &R, const Vec3 &size, Solid *s) {
  s->v.clear();
  for (int i = 0; i < 8; i++) {
    Vec3 h((i & 1 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(), (i & 4 ? 0.5 : -0.5) * size.z());
    s->v.push_back(c + R * h);
  }
  s->faces = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
}

void cylinder_solid(const Vec3 &c, const Mat3 &R, double r, double len, int n, Solid *s) {
  s->v.clear();
  s->faces.clear();
  for (int k = 0; k < 2; k++) {
    for (int i = 0; i < n; i++) {
      double a = 2 * M_PI * i / n;
      s->v.push_back(c + R * Vec3(r * std::cos(a), r * std::sin(a), (k ? 0.5 : -0.5) * len));
    }
  }
  std::vector<int> bottom, top;
  for (int i = 0; i < n; i++) {
    s->faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
  }
  s->faces.push_back(bottom);
  s->faces.push_back(top);
}

void set_yuv(Solid *s, int y, int u, int v) {
  s->yuv[0] = (unsigned char)y;
  s->yuv[1] = (unsigned char)u;
  s->yuv[2] = (unsigned char)v;
}

}  // namespace world_internal

using namespace world_internal;

int World::team(int r) const {
  if (r < (int)p_.robot_team.size()) return p_.robot_team[r];
  return r < ((int)robots_.size() + 1) / 2 ? 1 : 2;
}

void World::snapshot(Scene *s) const {
  s->first.resize(robots_.size());
  size_t n = 0;
  for (size_t r = 0; r < robots_.size(); r++) {
    s->first[r] = n;
    n += robots_[r].m->links.size();
  }
  s->link_pos.resize(n);
  s->link_rot.resize(n);
  for (size_t r = 0; r < robots_.size(); r++)
    for (size_t i = 0; i < robots_[r].m->links.size(); i++)
      link_pose((int)r, (int)i, &s->link_pos[s->first[r] + i], &s->link_rot[s->first[r] + i]);
  s->ball = ball_position();
  s->ball_rot = ball_rotation();
}

void World::solids(std::vector<Solid> *out) const {
  Scene s;
  snapshot(&s);
  solids(s, out);
}

void World::solids(const Scene &scene, std::vector<Solid> *out) const {
  out->clear();
  for (const Solid &s : goal_solids_) out->push_back(s);
  for (size_t r = 0; r < scene.first.size(); r++) {
    const Model &m = *robots_[r].m;
    for (size_t i = 0; i < m.links.size(); i++) {
      const Vec3 &p = scene.link_pos[scene.first[r] + i];
      const Mat3 &R = scene.link_rot[scene.first[r] + i];
      // the torso (the root link) wears the team's jersey, the head is dark, the rest grey
      const unsigned char *jersey = p_.team_yuv[team((int)r) - 1];
      const bool dark = m.links[i].name.find("head") != std::string::npos;
      for (const Box &b : m.links[i].boxes) {
        Solid s;
        box_solid(p + R * b.pos, R * b.rot, b.size, &s);
        if (i == 0) set_yuv(&s, jersey[0], jersey[1], jersey[2]);
        else if (dark) set_yuv(&s, 60, 128, 128);
        else set_yuv(&s, 120, 128, 128);
        s.robot = (int)r;
        s.link = (int)i;
        out->push_back(s);
      }
    }
  }
}

}  // namespace sim
