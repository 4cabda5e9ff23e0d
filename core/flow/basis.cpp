// Conversions between the Taylor, Waxman-Ullman and planar bases (dissertation eq. 28-36,
// corrected: see manual/theory.md#errata, items 5, 6, 8, 9).
#include "flow/basis.h"

#include <stdexcept>
#include <string>

namespace oflab {

TaylorTerms taylor_terms(const PlanarFlowCoefficients& c) {
  TaylorTerms t;
  t.v1 = c.tx;
  t.v2 = c.ty;
  t.v1_x = c.j11;
  t.v1_y = c.j12;
  t.v2_x = c.j21;
  t.v2_y = c.j22;
  t.v1_xx = 2.0 * c.px;
  t.v1_xy = c.py;
  t.v1_yy = 0.0;
  t.v2_xx = 0.0;
  t.v2_xy = c.px;
  t.v2_yy = 2.0 * c.py;
  return t;
}

WaxmanUllmanTerms to_waxman_ullman(const TaylorTerms& t) {
  WaxmanUllmanTerms w;
  w.v1 = t.v1;
  w.v2 = t.v2;
  w.e_xx = t.v1_x;
  w.e_yy = t.v2_y;
  w.e_xy = 0.5 * (t.v1_y + t.v2_x);
  w.omega = 0.5 * (t.v2_x - t.v1_y);
  w.e_xx_x = t.v1_xx;
  w.e_xx_y = t.v1_xy;
  w.e_yy_x = t.v2_xy;
  w.e_yy_y = t.v2_yy;
  w.omega_x = 0.5 * (t.v2_xx - t.v1_xy);
  w.omega_y = 0.5 * (t.v2_xy - t.v1_yy);
  return w;
}

TaylorTerms from_waxman_ullman(const WaxmanUllmanTerms& w) {
  TaylorTerms t;
  t.v1 = w.v1;
  t.v2 = w.v2;
  t.v1_x = w.e_xx;
  t.v2_y = w.e_yy;
  t.v1_y = w.e_xy - w.omega;
  t.v2_x = w.e_xy + w.omega;
  t.v1_xx = w.e_xx_x;
  t.v1_xy = w.e_xx_y;
  t.v2_xy = w.e_yy_x;
  t.v2_yy = w.e_yy_y;
  t.v2_xx = 2.0 * w.omega_x + t.v1_xy;
  t.v1_yy = t.v2_xy - 2.0 * w.omega_y;
  return t;
}

PlanarBasisTerms to_planar_basis(const TaylorTerms& t) {
  PlanarBasisTerms p;
  p.tx = t.v1;
  p.ty = t.v2;
  p.scale = 0.5 * (t.v1_x + t.v2_y);
  p.squash = 0.5 * (t.v2_y - t.v1_x);
  p.shear = 0.5 * (t.v1_y + t.v2_x);
  p.rotation = 0.5 * (t.v2_x - t.v1_y);
  p.v1_yy = t.v1_yy;
  p.v2_xx = t.v2_xx;
  p.non_planar_x = t.v1_xx / 3.0 - 2.0 * t.v2_xy / 3.0;
  p.non_planar_y = t.v2_yy / 3.0 - 2.0 * t.v1_xy / 3.0;
  p.px = 0.25 * t.v1_xx + 0.5 * t.v2_xy;
  p.py = 0.25 * t.v2_yy + 0.5 * t.v1_xy;
  return p;
}

TaylorTerms from_planar_basis(const PlanarBasisTerms& p) {
  TaylorTerms t;
  t.v1 = p.tx;
  t.v2 = p.ty;
  t.v1_x = p.scale - p.squash;
  t.v2_y = p.scale + p.squash;
  t.v1_y = p.shear - p.rotation;
  t.v2_x = p.shear + p.rotation;
  t.v1_yy = p.v1_yy;
  t.v2_xx = p.v2_xx;
  // Invert (non_planar, p) = (u/3 - 2w/3, u/4 + w/2) for (u, w) = (v1_xx, v2_xy), and alike.
  t.v1_xx = 1.5 * p.non_planar_x + 2.0 * p.px;
  t.v2_xy = p.px - 0.75 * p.non_planar_x;
  t.v2_yy = 1.5 * p.non_planar_y + 2.0 * p.py;
  t.v1_xy = p.py - 0.75 * p.non_planar_y;
  return t;
}

PlanarFlowCoefficients planar_coefficients(const PlanarBasisTerms& p) {
  const TaylorTerms t = from_planar_basis(p);
  PlanarFlowCoefficients c;
  c.tx = t.v1;
  c.ty = t.v2;
  c.j11 = t.v1_x;
  c.j12 = t.v1_y;
  c.j21 = t.v2_x;
  c.j22 = t.v2_y;
  c.px = p.px;
  c.py = p.py;
  return c;
}

Vec2 taylor_flow_at(const TaylorTerms& t, const Vec2& p) {
  const double x = p.x, y = p.y;
  return Vec2(t.v1 + t.v1_x * x + t.v1_y * y +
                  0.5 * (t.v1_xx * x * x + 2.0 * t.v1_xy * x * y + t.v1_yy * y * y),
              t.v2 + t.v2_x * x + t.v2_y * y +
                  0.5 * (t.v2_xx * x * x + 2.0 * t.v2_xy * x * y + t.v2_yy * y * y));
}

TaylorTerms taylor_order_terms(const TaylorTerms& t, int order) {
  TaylorTerms only;
  switch (order) {
    case 0:
      only.v1 = t.v1;
      only.v2 = t.v2;
      return only;
    case 1:
      only.v1_x = t.v1_x;
      only.v1_y = t.v1_y;
      only.v2_x = t.v2_x;
      only.v2_y = t.v2_y;
      return only;
    case 2:
      only = t;
      only.v1 = only.v2 = 0.0;
      only.v1_x = only.v1_y = only.v2_x = only.v2_y = 0.0;
      return only;
  }
  throw std::invalid_argument("taylor_order_terms: order " + std::to_string(order) +
                              " is not 0, 1 or 2");
}

}  // namespace oflab
