// The terms of the three bases of the flow's Taylor expansion (dissertation Fig. 14-16),
// listed for display: a name, an order, the flow of the term alone and how to read its
// coefficient off a flow. Plain C++ over core/flow/basis.h: each term's flow is core's
// taylor_flow_at of the Taylor terms that core's from_* conversion gives for that term
// alone, and each coefficient is read through core's to_* conversion.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "flow/basis.h"

namespace oflab {

enum class BasisKind { kTaylor, kWaxmanUllman, kPlanar };
constexpr int kBasisKindCount = 3;

const char* basis_title(BasisKind kind);  // e.g. "Planar basis (Fig. 16)"
const char* basis_key(BasisKind kind);    // "taylor", "waxman-ullman", "planar"
// Parses a key; false (and *kind unchanged) for anything else.
bool parse_basis_kind(const std::string& key, BasisKind* kind);

struct BasisTerm {
  std::string symbol;       // ASCII, e.g. "v1_x", "e_xx,y", "scale", "px"
  std::string description;  // a few words, e.g. "rotation (curl / 2)"
  int order = 0;            // 0 translation, 1 first order, 2 second order
  TaylorTerms unit;         // this term alone at value 1, as raw Taylor terms
  std::function<double(const TaylorTerms&)> coefficient;  // this term's value in a flow
};

// The 12 terms of a basis: 2 translation, 4 first-order, 6 second-order, in the order of
// the dissertation's figures.
std::vector<BasisTerm> basis_terms(BasisKind kind);

// Unit of a coefficient of the given order: "px/s", "1/s" or "1/(px s)".
const char* order_unit(int order);

// The coefficient as a displacement rate at distance radius_px from the expansion point
// (pixels per second): |value| * radius_px^order. Makes the orders comparable.
double rate_at_radius(int order, double value, double radius_px);

// True when the term contributes less than 1e-9 px/s anywhere within radius_px: such a
// coefficient is zero up to rounding, and the views grey it out.
bool is_negligible(int order, double value, double radius_px);

}  // namespace oflab
