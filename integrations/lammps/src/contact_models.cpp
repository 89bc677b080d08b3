/* Friction sub-models of the hertzdamp LAMMPS plugin: see contact_models.h. */
#include "contact_models.h"

#include "hertzdamp_lammps.h"

#include <cmath>

namespace HertzdampLammps {

namespace {

const double EPSILON = 1e-10;    // frame-update threshold relative to the Coulomb limit

inline double dot3(const double *a, const double *b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double len3(const double *a)
{
  return std::sqrt(dot3(a, a));
}

// Project v onto the plane normal to the unit vector n and give it back its length.
void rotate_rescale(double *v, const double *n)
{
  const double mag = len3(v), vn = dot3(v, n);
  for (int k = 0; k < 3; k++) v[k] -= vn * n[k];
  const double prj = len3(v);
  const double scale = prj > 0.0 ? mag / prj : 0.0;
  for (int k = 0; k < 3; k++) v[k] *= scale;
}

// Spring-dashpot-slider on a history vector h (tangential and rolling sub-models):
// h rotated into the tangent plane and advanced by dt w; force f = -k h - g w limited to
// |f| <= fcrit, with h reset to the elastic part of the limited force.
void spring_slider(double k, double g, double fcrit, const double *w, const double *nx, double dt,
                   int update, double *h, double *f)
{
  if (update) {
    if (std::fabs(dot3(h, nx)) * k > EPSILON * fcrit) rotate_rescale(h, nx);
    for (int c = 0; c < 3; c++) h[c] += dt * w[c];
  }
  for (int c = 0; c < 3; c++) f[c] = -k * h[c] - g * w[c];
  const double fmag = len3(f);
  if (fmag > fcrit) {
    if (len3(h) != 0.0) {
      for (int c = 0; c < 3; c++) {
        h[c] = -1.0 / k * (fcrit * f[c] / fmag + g * w[c]);
        f[c] *= fcrit / fmag;
      }
    } else {
      f[0] = f[1] = f[2] = 0.0;
    }
  }
}

// The scalar version for twisting: torque -k h - g w limited to |M| <= mcrit.
double twist_slider(double k, double g, double mcrit, double w, double dt, int update, double *h)
{
  if (update) *h += w * dt;
  double m = -k * *h - g * w;
  if (std::fabs(m) > mcrit) {
    const double sign = static_cast<double>((w > 0.0) - (w < 0.0));
    *h = 1.0 / k * (mcrit * sign - g * w);
    m = -mcrit * sign;
  }
  return m;
}

}    // namespace

/* ---------------------------------------------------------------------- */

void friction_forces(const FrictionModel &fm, double kt_eff, const ContactState &s, double *hist,
                     double fs[3], double fr[3], double &mt)
{
  fs[0] = fs[1] = fs[2] = fr[0] = fr[1] = fr[2] = 0.0;
  mt = 0.0;
  if (fm.tangential == TANG_NONE) return;

  const bool needs_a = fm.tangential == TANG_MINDLIN || fm.twisting == TWIST_MARSHALL;
  const double a = needs_a ? std::sqrt(s.delta * s.reff) : 0.0;    // Hertz contact radius
  const double k_t = fm.tangential == TANG_MINDLIN ? kt_eff * a : kt_eff;
  const double damp_t = fm.xt * s.damp_n;
  spring_slider(k_t, damp_t, fm.mut * s.fncrit, s.vtr, s.nx, s.dt, s.history_update, hist, fs);

  if (fm.rolling == ROLL_SDS) {
    // rolling velocity R_eff (omega_i - omega_j) x n (Wang et al., Particuology 23, 2015)
    const double *w = s.relrot, *n = s.nx;
    const double vrl[3] = {s.reff * (w[1] * n[2] - w[2] * n[1]), s.reff * (w[2] * n[0] - w[0] * n[2]),
                           s.reff * (w[0] * n[1] - w[1] * n[0])};
    spring_slider(fm.kr, fm.gr, fm.mur * s.fncrit, vrl, s.nx, s.dt, s.history_update, hist + 3, fr);
  }

  if (fm.twisting != TWIST_NONE) {
    double k = fm.ktw, g = fm.gtw, mu = fm.mutw;
    if (fm.twisting == TWIST_MARSHALL) {
      // Marshall (J. Comput. Phys. 228, 2009) eq. 32, from the tangential model.  LAMMPS
      // 2021 takes the mindlin stiffness already multiplied by a, later versions do not.
#if HERTZDAMP_LAMMPS_NUM < 20230000
      const double kt_twist = k_t;
#else
      const double kt_twist = kt_eff;
#endif
      k = 0.5 * kt_twist * a * a;
      g = 0.5 * damp_t * a * a;
      mu = 2.0 / 3.0 * a * fm.mut;
    }
    mt = twist_slider(k, g, mu * s.fncrit, dot3(s.relrot, s.nx), s.dt, s.history_update, hist + 6);
  }
}

/* ---------------------------------------------------------------------- */

int FrictionModel::parse(LAMMPS_NS::LAMMPS *lmp, const std::string &cmd, int narg, char **arg, int iarg)
{
  const std::string key = arg[iarg];
  if (key != "tangential" && key != "rolling" && key != "twisting") return 0;
  if (iarg + 1 >= narg) fail_all(lmp, __FILE__, __LINE__, cmd + ": keyword '" + key + "' needs a model name");
  const std::string model = arg[iarg + 1];
  const std::string what = key + " " + model;
  auto need = [&](int n) {
    if (iarg + 1 + n >= narg)
      fail_all(lmp, __FILE__, __LINE__, cmd + ": '" + what + "' needs " + std::to_string(n) + " values");
  };
  auto num = [&](int k, const char *name) {
    const double x = parse_number(lmp, cmd, (what + " " + name).c_str(), arg[iarg + 1 + k]);
    if (!(x >= 0.0)) fail_all(lmp, __FILE__, __LINE__, cmd + ": " + what + " " + name + " must be >= 0");
    return x;
  };
  if (key == "tangential") {
    if (model != "linear_history" && model != "mindlin")
      fail_all(lmp, __FILE__, __LINE__, cmd + ": tangential model must be linear_history or mindlin, not '" + model + "'");
    need(3);
    tangential = model == "mindlin" ? TANG_MINDLIN : TANG_LINEAR_HISTORY;
    if (tangential == TANG_MINDLIN && std::string(arg[iarg + 2]) == "NULL")
      kt = -1.0;
    else
      kt = num(1, "kt");
    xt = num(2, "xgammat");
    mut = num(3, "mu");
    return 5;
  }
  if (key == "rolling") {
    if (model != "sds") fail_all(lmp, __FILE__, __LINE__, cmd + ": rolling model must be sds, not '" + model + "'");
    need(3);
    rolling = ROLL_SDS;
    kr = num(1, "kR");
    gr = num(2, "gammaR");
    mur = num(3, "muR");
    if (!(kr > 0.0)) fail_all(lmp, __FILE__, __LINE__, cmd + ": rolling sds kR must be > 0");
    return 5;
  }
  if (model == "marshall") {
    twisting = TWIST_MARSHALL;
    return 2;
  }
  if (model != "sds") fail_all(lmp, __FILE__, __LINE__, cmd + ": twisting model must be marshall or sds, not '" + model + "'");
  need(3);
  twisting = TWIST_SDS;
  ktw = num(1, "kT");
  gtw = num(2, "gammaT");
  mutw = num(3, "muT");
  if (!(ktw > 0.0)) fail_all(lmp, __FILE__, __LINE__, cmd + ": twisting sds kT must be > 0");
  return 5;
}

void FrictionModel::check(LAMMPS_NS::LAMMPS *lmp, const std::string &cmd, bool has_material) const
{
  if (tangential == TANG_NONE && (rolling != ROLL_NONE || twisting != TWIST_NONE))
    fail_all(lmp, __FILE__, __LINE__, cmd + ": rolling and twisting need a tangential model");
  if (tangential != TANG_NONE && kt == 0.0 && twisting == TWIST_MARSHALL)
    fail_all(lmp, __FILE__, __LINE__, cmd + ": twisting marshall needs a tangential kt > 0");
  if (tangential != TANG_NONE && kt == 0.0)
    fail_all(lmp, __FILE__, __LINE__, cmd + ": tangential kt must be > 0");
  if (kt < 0.0 && !has_material)
    fail_all(lmp, __FILE__, __LINE__, cmd + ": tangential mindlin NULL needs youngs Y poisson NU (the shear modulus)");
}

FrictionModel FrictionModel::mix(const FrictionModel &a, const FrictionModel &b)
{
  FrictionModel m = a;
  auto g = [](double x, double y) { return std::sqrt(x * y); };
  m.kt = (a.kt < 0.0 || b.kt < 0.0) ? -1.0 : g(a.kt, b.kt);
  m.xt = g(a.xt, b.xt);
  m.mut = g(a.mut, b.mut);
  m.kr = g(a.kr, b.kr);
  m.gr = g(a.gr, b.gr);
  m.mur = g(a.mur, b.mur);
  m.ktw = g(a.ktw, b.ktw);
  m.gtw = g(a.gtw, b.gtw);
  m.mutw = g(a.mutw, b.mutw);
  return m;
}

std::string FrictionModel::describe() const
{
  if (tangential == TANG_NONE) return "no friction";
  std::string s = tangential == TANG_MINDLIN ? "tangential mindlin " : "tangential linear_history ";
  s += (kt < 0.0 ? std::string("NULL") : fmt_g(kt)) + " " + fmt_g(xt) + " " + fmt_g(mut);
  if (rolling == ROLL_SDS) s += " rolling sds " + fmt_g(kr) + " " + fmt_g(gr) + " " + fmt_g(mur);
  if (twisting == TWIST_MARSHALL) s += " twisting marshall";
  if (twisting == TWIST_SDS) s += " twisting sds " + fmt_g(ktw) + " " + fmt_g(gtw) + " " + fmt_g(mutw);
  return s;
}

}    // namespace HertzdampLammps
