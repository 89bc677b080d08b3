/* -*- c++ -*-
 * Tangential, rolling and twisting sub-models of the hertzdamp LAMMPS plugin, with the
 * keywords, coefficients and formulas of LAMMPS's `pair_style granular` (doc page
 * "pair_style granular"; GRANULAR/gran_sub_mod_tangential.cpp, _rolling.cpp, _twisting.cpp),
 * written for this project:
 *
 *   tangential linear_history kt xgammat mu       F_t = -kt xi - eta_t v_t,rel, |F_t| <= mu F_n,crit
 *   tangential mindlin (NULL|kt) xgammat mu       the same with kt a (a = sqrt(delta R_eff));
 *                                                 NULL: kt = 8 G*, G* from youngs/poisson
 *   rolling sds kR gammaR muR                     F_r = -kR xi_r - gammaR v_rl, |F_r| <= muR F_n,crit
 *   twisting marshall                             k = kt a^2/2, eta = eta_t a^2/2, mu = 2/3 a mu_t
 *   twisting sds kT gammaT muT                    M_t = -kT xi_t - gammaT w_t, |M_t| <= muT F_n,crit
 *
 * eta_t = xgammat d, with d the contact's normal damping (the hertzdamp rule's d: LAMMPS's
 * `damping velocity` prefactor); F_n,crit = |F_n| (the normal force without the phase
 * correction, clipped at zero with `end force`).  The history (xi, xi_r, xi_t) is
 * rotated into the current tangent plane with its length kept, advanced by dt times the
 * half-step relative velocity, and reset to the elastic part of the force when the
 * Coulomb limit is reached.  The history is not advanced in the force computation of a
 * run's set-up (as LAMMPS does).
 */
#ifndef HERTZDAMP_CONTACT_MODELS_H
#define HERTZDAMP_CONTACT_MODELS_H

#include "lammps.h"

#include <string>

namespace HertzdampLammps {

enum TangentialModel { TANG_NONE, TANG_LINEAR_HISTORY, TANG_MINDLIN };
enum RollingModel { ROLL_NONE, ROLL_SDS };
enum TwistingModel { TWIST_NONE, TWIST_MARSHALL, TWIST_SDS };

// The friction sub-models of one type pair (pair_coeff) or one wall fix.
struct FrictionModel {
  int tangential = TANG_NONE;
  double kt = 0.0, xt = 0.0, mut = 0.0;    // kt < 0: mindlin NULL (from the materials)
  int rolling = ROLL_NONE;
  double kr = 0.0, gr = 0.0, mur = 0.0;
  int twisting = TWIST_NONE;
  double ktw = 0.0, gtw = 0.0, mutw = 0.0;

  bool any() const { return tangential != TANG_NONE; }
  // Parse `tangential ...`, `rolling ...` or `twisting ...` at arg[iarg]; returns the
  // number of words used, 0 if arg[iarg] is none of them.  Errors name the keyword.
  int parse(LAMMPS_NS::LAMMPS *lmp, const std::string &cmd, int narg, char **arg, int iarg);
  // After all keywords: rolling/twisting need a tangential model; mindlin NULL needs
  // materials (has_material).
  void check(LAMMPS_NS::LAMMPS *lmp, const std::string &cmd, bool has_material) const;
  bool same_models(const FrictionModel &o) const
  {
    return tangential == o.tangential && rolling == o.rolling && twisting == o.twisting &&
        (kt < 0.0) == (o.kt < 0.0);
  }
  // I-J from I-I and J-J: geometric means of the coefficients (as pair_style granular)
  static FrictionModel mix(const FrictionModel &a, const FrictionModel &b);
  std::string describe() const;
};

// Shear modulus of a contact: 1/G* = 2 (2 - nu1)(1 + nu1)/E1 + 2 (2 - nu2)(1 + nu2)/E2.
inline double effective_shear_modulus(double y1, double nu1, double y2, double nu2)
{
  return 1.0 / (2.0 * (2.0 - nu1) * (1.0 + nu1) / y1 + 2.0 * (2.0 - nu2) * (1.0 + nu2) / y2);
}

// Geometry and kinematics of one contact in one step.
struct ContactState {
  double nx[3];        // unit normal, from j (or the wall) to i
  double vtr[3];       // relative tangential velocity at the contact point
  double relrot[3];    // omega_i - omega_j
  double delta;        // overlap
  double reff;         // R_eff
  double fncrit;       // |normal force|
  double damp_n;       // normal damping coefficient d of the contact
  double dt;
  int history_update;  // 0 in the set-up force computation
};

// Friction of one contact: tangential force fs, rolling force fr and twisting torque
// magnitude mt; advances the history hist (7 doubles: 3 tangential, 3 rolling, 1 twist).
// kt_eff: the tangential stiffness coefficient (mindlin NULL resolved to 8 G*).
void friction_forces(const FrictionModel &fm, double kt_eff, const ContactState &s, double *hist,
                     double fs[3], double fr[3], double &mt);

}    // namespace HertzdampLammps

#endif
