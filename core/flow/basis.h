// The three bases of the flow's Taylor terms the dissertation discusses (section 4.5-4.8,
// Fig. 14-16), with exact conversions. Units: zeroth order pixels per unit time, first
// order per unit time, second order per pixel per unit time. Derivatives are with
// respect to centred pixels at the expansion point; "v1_xy" means d^2 v_x / dx dy.
#pragma once

#include "flow/flow_field.h"

namespace oflab {

// Raw Taylor terms (Fig. 14): translation, 4 first-order and 6 second-order derivatives.
struct TaylorTerms {
  double v1 = 0.0, v2 = 0.0;                              // translation (tx, ty)
  double v1_x = 0.0, v1_y = 0.0, v2_x = 0.0, v2_y = 0.0;  // first order
  double v1_xx = 0.0, v1_xy = 0.0, v1_yy = 0.0;           // second order of v_x
  double v2_xx = 0.0, v2_xy = 0.0, v2_yy = 0.0;           // second order of v_y
};

// Waxman-Ullman terms (Fig. 15, eq. 28-30 corrected: symmetric part = rate of strain,
// e_yy = dv2/dy, omega = curl/2). The second order terms are the gradients of e_xx, e_yy
// and omega (eq. 30).
struct WaxmanUllmanTerms {
  double v1 = 0.0, v2 = 0.0;
  double e_xx = 0.0, e_yy = 0.0, e_xy = 0.0, omega = 0.0;
  double e_xx_x = 0.0, e_xx_y = 0.0, e_yy_x = 0.0, e_yy_y = 0.0, omega_x = 0.0, omega_y = 0.0;
};

// The planar basis (Fig. 16, eq. 35-36 corrected): scale, squash, shear (e_xy), rotation
// (omega) at first order; at second order four terms that vanish for any moving plane
// (v1_yy, v2_xx, and the two "non-planar" combinations) and the perspective terms px, py.
struct PlanarBasisTerms {
  double tx = 0.0, ty = 0.0;
  double scale = 0.0, squash = 0.0, shear = 0.0, rotation = 0.0;
  double v1_yy = 0.0, v2_xx = 0.0;
  double non_planar_x = 0.0;  // v1_xx/3 - 2 v2_xy/3
  double non_planar_y = 0.0;  // v2_yy/3 - 2 v1_xy/3
  double px = 0.0;            // v1_xx/4 + v2_xy/2 (erratum 8: the printed eq. 35 is wrong)
  double py = 0.0;            // v2_yy/4 + v1_xy/2
};

// The Taylor terms of a planar flow: v1_yy = v2_xx = 0, v1_xx = 2 px = 2 v2_xy,
// v2_yy = 2 py = 2 v1_xy (eq. 34).
TaylorTerms taylor_terms(const PlanarFlowCoefficients& c);

WaxmanUllmanTerms to_waxman_ullman(const TaylorTerms& t);
TaylorTerms from_waxman_ullman(const WaxmanUllmanTerms& w);
PlanarBasisTerms to_planar_basis(const TaylorTerms& t);
TaylorTerms from_planar_basis(const PlanarBasisTerms& p);

// The 8 planar coefficients from planar-basis terms (ignores the four non-planar terms).
PlanarFlowCoefficients planar_coefficients(const PlanarBasisTerms& p);

// The flow of arbitrary Taylor terms (quadratic polynomial) at centred offset p.
Vec2 taylor_flow_at(const TaylorTerms& t, const Vec2& p);

// The terms of one order alone, the others zero: order 0 the translation (v1, v2), 1 the
// first-order (affine) derivatives, 2 the second-order (perspective) ones; their flows add
// up to the flow of `t`. Throws std::invalid_argument for any other order.
TaylorTerms taylor_order_terms(const TaylorTerms& t, int order);

}  // namespace oflab
