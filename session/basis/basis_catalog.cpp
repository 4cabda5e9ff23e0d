#include "basis/basis_catalog.h"

#include <cmath>

namespace oflab {
namespace {

// One row of a basis table: the member of the basis struct that holds the term.
template <typename Terms>
struct TermRow {
  const char* symbol;
  const char* description;
  int order;
  double Terms::*member;
};

// Builds the catalogue of a basis from its member table and core's two conversions.
template <typename Terms>
std::vector<BasisTerm> make_terms(const std::vector<TermRow<Terms>>& rows,
                                  Terms (*to_basis)(const TaylorTerms&),
                                  TaylorTerms (*from_basis)(const Terms&)) {
  std::vector<BasisTerm> terms;
  for (const TermRow<Terms>& row : rows) {
    Terms alone;
    alone.*row.member = 1.0;
    const auto member = row.member;
    terms.push_back({row.symbol, row.description, row.order, from_basis(alone),
                     [to_basis, member](const TaylorTerms& t) { return to_basis(t).*member; }});
  }
  return terms;
}

TaylorTerms identity(const TaylorTerms& t) { return t; }

std::vector<BasisTerm> taylor_catalog() {
  using T = TaylorTerms;
  return make_terms<T>({{"v1", "translation in x", 0, &T::v1},
                        {"v2", "translation in y", 0, &T::v2},
                        {"v1_x", "x stretch (dv1/dx)", 1, &T::v1_x},
                        {"v1_y", "x shear along y (dv1/dy)", 1, &T::v1_y},
                        {"v2_x", "y shear along x (dv2/dx)", 1, &T::v2_x},
                        {"v2_y", "y stretch (dv2/dy)", 1, &T::v2_y},
                        {"v1_xx", "d2v1/dx2", 2, &T::v1_xx},
                        {"v1_xy", "d2v1/dxdy", 2, &T::v1_xy},
                        {"v1_yy", "d2v1/dy2 (zero for a plane)", 2, &T::v1_yy},
                        {"v2_xx", "d2v2/dx2, arching (zero for a plane)", 2, &T::v2_xx},
                        {"v2_xy", "d2v2/dxdy", 2, &T::v2_xy},
                        {"v2_yy", "d2v2/dy2", 2, &T::v2_yy}},
                       &identity, &identity);
}

std::vector<BasisTerm> waxman_ullman_catalog() {
  using W = WaxmanUllmanTerms;
  return make_terms<W>({{"v1", "translation in x", 0, &W::v1},
                        {"v2", "translation in y", 0, &W::v2},
                        {"e_xx", "strain rate xx", 1, &W::e_xx},
                        {"e_yy", "strain rate yy", 1, &W::e_yy},
                        {"e_xy", "shear strain rate", 1, &W::e_xy},
                        {"omega", "spin (curl / 2)", 1, &W::omega},
                        {"e_xx,x", "gradient of e_xx in x", 2, &W::e_xx_x},
                        {"e_xx,y", "gradient of e_xx in y", 2, &W::e_xx_y},
                        {"e_yy,x", "gradient of e_yy in x", 2, &W::e_yy_x},
                        {"e_yy,y", "gradient of e_yy in y", 2, &W::e_yy_y},
                        {"omega,x", "gradient of spin in x", 2, &W::omega_x},
                        {"omega,y", "gradient of spin in y", 2, &W::omega_y}},
                       &to_waxman_ullman, &from_waxman_ullman);
}

std::vector<BasisTerm> planar_catalog() {
  using P = PlanarBasisTerms;
  return make_terms<P>({{"tx", "translation in x", 0, &P::tx},
                        {"ty", "translation in y", 0, &P::ty},
                        {"scale", "uniform scaling (divergence / 2)", 1, &P::scale},
                        {"squash", "squash: y grows, x shrinks", 1, &P::squash},
                        {"shear", "shear (e_xy)", 1, &P::shear},
                        {"rotation", "rotation (curl / 2)", 1, &P::rotation},
                        {"v1_yy", "zero for any plane", 2, &P::v1_yy},
                        {"v2_xx", "zero for any plane", 2, &P::v2_xx},
                        {"np_x", "v1_xx/3 - 2 v2_xy/3, zero for a plane", 2, &P::non_planar_x},
                        {"np_y", "v2_yy/3 - 2 v1_xy/3, zero for a plane", 2, &P::non_planar_y},
                        {"px", "perspective in x", 2, &P::px},
                        {"py", "perspective in y", 2, &P::py}},
                       &to_planar_basis, &from_planar_basis);
}

}  // namespace

const char* basis_title(BasisKind kind) {
  switch (kind) {
    case BasisKind::kTaylor:
      return "Raw Taylor terms (Fig. 14)";
    case BasisKind::kWaxmanUllman:
      return "Waxman-Ullman (Fig. 15)";
    case BasisKind::kPlanar:
      return "Planar basis (Fig. 16)";
  }
  return "?";
}

const char* basis_key(BasisKind kind) {
  switch (kind) {
    case BasisKind::kTaylor:
      return "taylor";
    case BasisKind::kWaxmanUllman:
      return "waxman-ullman";
    case BasisKind::kPlanar:
      return "planar";
  }
  return "?";
}

bool parse_basis_kind(const std::string& key, BasisKind* kind) {
  for (int k = 0; k < kBasisKindCount; ++k) {
    if (key == basis_key(static_cast<BasisKind>(k))) {
      *kind = static_cast<BasisKind>(k);
      return true;
    }
  }
  return false;
}

std::vector<BasisTerm> basis_terms(BasisKind kind) {
  switch (kind) {
    case BasisKind::kTaylor:
      return taylor_catalog();
    case BasisKind::kWaxmanUllman:
      return waxman_ullman_catalog();
    case BasisKind::kPlanar:
      return planar_catalog();
  }
  return {};
}

const char* order_unit(int order) {
  switch (order) {
    case 0:
      return "px/s";
    case 1:
      return "1/s";
    default:
      return "1/(px s)";
  }
}

double rate_at_radius(int order, double value, double radius_px) {
  return std::abs(value) * std::pow(radius_px, order);
}

bool is_negligible(int order, double value, double radius_px) {
  return rate_at_radius(order, value, radius_px) < 1e-9;
}

}  // namespace oflab
