// Benchmark of the rigid-body model (`make bench`, BENCH=dynamics): Pinocchio's own RNEA, CRBA and
// joint Jacobians, then the same through Modules/dynamics' C ABI (each after a new state, so
// nothing is cached), and one whole-body query set as a controller tick needs it. Median, p99
// and max per call in microseconds, at random configurations; never fails on time.
//   build/bin/dyn_bench [samples] [body]
#include "dynamics/dyn_model.hpp"

#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/jacobian.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/algorithm/rnea.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace {

// Times f() once per sample after prep() (not timed); prints median, p99, max.
template <class P, class F> void report(const char *name, int n, P prep, F f) {
  std::vector<double> t(n);
  for (int i = 0; i < n / 10; i++) prep(i), f();   // warm up
  for (int i = 0; i < n; i++) {
    prep(i);
    auto t0 = std::chrono::steady_clock::now();
    f();
    t[i] = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
  }
  std::sort(t.begin(), t.end());
  printf("%-44s median %7.2f us   p99 %7.2f us   max %8.2f us\n", name, t[n / 2], t[(size_t)(n * 0.99)], t[n - 1]);
}

}  // namespace

int main(int argc, char **argv) {
  int n = argc > 1 ? atoi(argv[1]) : 20000;
  std::string body = argc > 2 ? argv[2] : "hubo2plus";
  const char *env = getenv("HRP_ROOT");
  std::string root = env && *env ? env : HRP_ROOT_DEFAULT;
  std::string urdf = root + "/Config/robots/" + body + "/" + body + ".urdf";
  char err[512];
  dyn_model *m = nullptr;
  if (dyn_model_load(urdf.c_str(), 0, nullptr, &m, err, sizeof err) != 0) {
    fprintf(stderr, "dyn_bench: %s\n", err);
    return 1;
  }
  const pinocchio::Model &model = m->model;
  pinocchio::Data data(model);
  int nv = model.nv, nj = dyn_njoint(m);
  printf("rigid-body model of %s: %d joints + floating base (nv %d), %d frames; %d samples each\n", body.c_str(), nj,
         nv, dyn_nframe(m), n);

  // Random states, prepared before timing.
  const int NS = 64;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::VectorXd> qs, vs, as;
  std::vector<std::vector<double>> bases, qjs;
  for (int s = 0; s < NS; s++) {
    Eigen::VectorXd one = Eigen::VectorXd::Ones(model.nq);
    qs.push_back(pinocchio::randomConfiguration(model, -one, one));
    vs.push_back(Eigen::VectorXd::NullaryExpr(nv, [&] { return u(rng); }));
    as.push_back(Eigen::VectorXd::NullaryExpr(nv, [&] { return u(rng); }));
    bases.push_back(std::vector<double>(qs[s].data(), qs[s].data() + 7));
    qjs.push_back(std::vector<double>(qs[s].data() + 7, qs[s].data() + model.nq));
  }
  auto none = [](int) {};
  int k = 0;
  report("Pinocchio rnea (q, v, a)", n, [&](int i) { k = i % NS; },
         [&] { pinocchio::rnea(model, data, qs[k], vs[k], as[k]); });
  report("Pinocchio crba", n, [&](int i) { k = i % NS; }, [&] { pinocchio::crba(model, data, qs[k]); });
  report("Pinocchio computeJointJacobians", n, [&](int i) { k = i % NS; },
         [&] { pinocchio::computeJointJacobians(model, data, qs[k]); });

  std::vector<double> J(6 * nv), Jc(3 * nv), M(nv * nv), h(nv), tau(nv), c(3);
  auto state = [&](int i) {
    k = i % NS;
    dyn_set_state(m, bases[k].data(), qjs[k].data(), vs[k].data());
  };
  const char *tips[4] = {"l_sole", "r_sole", "l_palm", "r_palm"};
  int frames[4];
  for (int t = 0; t < 4; t++) frames[t] = std::max(0, dyn_frame_id(m, tips[t]));
  report("dyn_set_state", n, none, [&] { state(k + 1); });
  report("dyn_inverse_dynamics (RNEA)", n, state, [&] { dyn_inverse_dynamics(m, as[k].data(), tau.data()); });
  report("dyn_nonlinear (RNEA, a = 0)", n, state, [&] { dyn_nonlinear(m, h.data()); });
  report("dyn_mass_matrix (CRBA)", n, state, [&] { dyn_mass_matrix(m, M.data()); });
  report("dyn_frame_jacobian, first after a state", n, state,
         [&] { dyn_frame_jacobian(m, frames[3], DYN_WORLD_ALIGNED, J.data()); });
  report("dyn_com with its Jacobian", n, state, [&] { dyn_com(m, c.data(), Jc.data()); });
  report("one tick: 4 frame Jacobians, COM, M, h", n, none, [&] {
    state(k + 1);
    for (int t = 0; t < 4; t++) dyn_frame_jacobian(m, frames[t], DYN_WORLD_ALIGNED, J.data());
    dyn_com(m, c.data(), Jc.data());
    dyn_mass_matrix(m, M.data());
    dyn_nonlinear(m, h.data());
  });
  dyn_model_destroy(m);
  return 0;
}
