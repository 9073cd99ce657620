// pressure: point pressure sensors under a sole (robot.lua `foot_pressure`), as the sim models them.
//
// The sensors sit between the foot and a rigid sole plate; the plate rests on them. Each reads the
// normal force it carries. Which share of the sole's load each carries is statically indeterminate
// with more than three sensors; the model takes them as equally stiff springs under a rigid plate
// (the plate's deflection is a plane, each sensor's force proportional to its own), and
// compression-only: a sensor the plate would pull on reads 0 and the plate rests on the others. So
// the sensors' centre of pressure is the sole's own wherever that lies inside the convex hull of the
// sensors; outside it (between the sensors and the sole's edge) the plate bears on the hull's edge
// and the sensors read the point of the hull nearest it, as real sensors under a plate would: they
// carry no more. Not modelled (no data): each sensor's calibration, noise, range and dynamics.
#ifndef HRP_SIM_PRESSURE_H
#define HRP_SIM_PRESSURE_H

#include <vector>

namespace sim {

// The forces (N, >= 0, summing to fz) the sensors at xy (x0 y0 x1 y1 ..., m, the sole's frame) carry
// when the sole carries the normal force fz (N) with its centre of pressure at (cx, cy); all 0 when
// fz <= 0 or not finite. At least three sensors, not all on one line (checked where they are read).
std::vector<double> pressure_distribute(const std::vector<double> &xy, double fz, double cx, double cy);

// True when the points (x0 y0 x1 y1 ...) are at least three and not all on one line (within 1 mm).
bool pressure_layout_ok(const std::vector<double> &xy);

}  // namespace sim
#endif
