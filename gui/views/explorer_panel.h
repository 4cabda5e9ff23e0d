// The basis explorer's widgets (session/basis/basis_explorer.h), which the basis view lays out
// around its gallery when the explorer is on: a column of eight sliders, one per planar-basis
// term with its unit (SliderSpin), with the solutions of the inverse problem as numbers under
// them; the picture of their combined deformation; and a column with the two solutions
// sketched as planes and the two played forward for a second (a button, a chart of the pixel
// distance per frame and a line naming the frame they part). The sliders edit the window model's
// explorer values; everything else reads them.
#pragma once

#include <QObject>
#include <QString>
#include <array>
#include <vector>

#include "adapters/view_theme.h"
#include "basis/basis_explorer.h"

class QLabel;
class QPushButton;
class QTimer;
class QWidget;

namespace oflab {

class ImageCanvas;
class SliderSpin;
class WindowModel;

class ExplorerPanel : public QObject {
  Q_OBJECT

 public:
  // Makes the three widgets as children of `parent`; `window` must outlive the panel.
  ExplorerPanel(WindowModel* window, QWidget* parent);
  ~ExplorerPanel() override;

  // The sliders, their buttons and the solutions as numbers.
  QWidget* dials() const { return dials_; }
  ImageCanvas* deformation() const { return deformation_; }
  // The solutions' sketches and the futures: the button, the chart and its line.
  QWidget* worlds() const { return worlds_; }

  // Reads the model's values into the sliders and solves and draws them (when `visible`;
  // otherwise only marks the pictures out of date until the next refresh).
  void refresh(bool visible);
  void set_theme(const ViewTheme& theme);
  // When on, the futures' timer stays stopped and only step_futures advances the play.
  void set_external_clock(bool on);

  // Plays the two futures from frame 0 (a timer at 30 frames per second, or step_futures).
  void play_futures();
  // One frame of that play; the last frame stops it.
  void step_futures();
  bool futures_playing() const { return futures_playing_; }
  // The frame of the futures shown (the last frame played when not playing).
  int futures_frame() const { return futures_frame_; }

  // What the panel shows now, for tests and lesson claims.
  const ExplorerResult& result() const { return result_; }
  QString solutions_text() const;
  QString futures_text() const;
  SliderSpin* slider(int index) const { return sliders_of_[size_t(index)]; }
  // What is wrong with the texts the panel shows, one sentence each (empty when every word
  // shows whole): the painted pictures' texts elided, off their canvas or overlapping
  // (text_problems of gui/adapters/painted_text.h), and a label (the title, the solutions,
  // the futures' line) shorter than its wrapped text needs or reaching past its column.
  std::vector<QString> text_problems() const;
  // The share (0..1) of the deformation picture under its caption that the deformed texture
  // rectangle covers, at the canvas's size (explorer_deformation_fill); 0 while it is hidden.
  double deformation_fill() const;
  // The smallest text of the painted pictures, pixels.
  double smallest_text_px() const { return theme_.label_size; }

 private:
  QWidget* make_dials(QWidget* parent);
  QWidget* make_worlds(QWidget* parent);
  void solve();
  void paint();
  void paint_futures();
  void fit_sliders();

  WindowModel* window_;
  ViewTheme theme_;
  QWidget* dials_ = nullptr;
  ImageCanvas* deformation_ = nullptr;
  QWidget* worlds_ = nullptr;
  std::array<SliderSpin*, kExplorerTermCount> sliders_of_{};
  QLabel* solutions_ = nullptr;
  ImageCanvas* sketch_ = nullptr;
  QPushButton* play_ = nullptr;
  ImageCanvas* futures_ = nullptr;
  QLabel* futures_line_ = nullptr;
  QTimer* timer_ = nullptr;
  ExplorerResult result_;
  int futures_frame_ = 0;
  bool futures_playing_ = false;
  bool external_clock_ = false;
  bool solved_ = false;
};

}  // namespace oflab
