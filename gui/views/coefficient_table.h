// The side table of the flow view: the current flow's coefficients in the chosen basis
// (raw Taylor, Waxman-Ullman or planar), one row per term with its value and unit.
// Terms that are zero up to rounding are greyed, so for a plane the table shows which
// terms a plane can never excite. No cell is ever elided: the columns fit the widest value
// the table can show in the current font (presentation mode included).
#pragma once

#include <QWidget>

#include "basis/basis_catalog.h"

class QComboBox;
class QTableWidget;

namespace oflab {

class CoefficientTable : public QWidget {
  Q_OBJECT

 public:
  explicit CoefficientTable(QWidget* parent = nullptr);

  // Shows the terms of `flow` (Taylor terms about the principal point) in the chosen
  // basis; radius_px is the half-diagonal of the image, used to decide what is zero.
  void show_terms(const TaylorTerms& flow, double radius_px);

  BasisKind basis() const;
  void set_basis(BasisKind kind);

  // The displayed text of a row's value cell (for tests), or empty if out of range.
  QString value_text(int row) const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void refill();
  // Columns wide enough for every symbol, unit and any value the table can show (so
  // nothing is elided), rows tall enough for the font, and the table at least as wide.
  void fit_columns();

  QComboBox* basis_box_;
  QTableWidget* table_;
  TaylorTerms flow_;
  double radius_px_ = 1.0;
  int shown_basis_ = -1;  // basis of the current rows
};

}  // namespace oflab
