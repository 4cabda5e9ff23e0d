#include "adapters/painted_text.h"

#include <QPaintDevice>
#include <QPaintEngine>
#include <QPainter>
#include <QTransform>
#include <algorithm>

namespace oflab {
namespace {

constexpr QChar kEllipsis(0x2026);

// Claims every feature so that the painter hands it text items and primitives in logical
// coordinates instead of emulating them; keeps the text and drops everything else.
class TextRecordingEngine final : public QPaintEngine {
 public:
  TextRecordingEngine() : QPaintEngine(QPaintEngine::AllFeatures) {}
  bool begin(QPaintDevice*) override { return true; }
  bool end() override { return true; }
  Type type() const override { return QPaintEngine::User; }
  void updateState(const QPaintEngineState& state) override {
    if (state.state() & QPaintEngine::DirtyTransform) transform_ = state.transform();
  }
  void drawTextItem(const QPointF& p, const QTextItem& item) override {
    const QRectF box(p.x(), p.y() - item.ascent(), item.width(), item.ascent() + item.descent());
    texts.push_back({item.text(), transform_.mapRect(box)});
  }
  void drawPixmap(const QRectF&, const QPixmap&, const QRectF&) override {}
  void drawImage(const QRectF&, const QImage&, const QRectF&, Qt::ImageConversionFlags) override {}
  void drawTiledPixmap(const QRectF&, const QPixmap&, const QPointF&) override {}
  void drawPolygon(const QPointF*, int, PolygonDrawMode) override {}
  void drawPolygon(const QPoint*, int, PolygonDrawMode) override {}
  void drawPath(const QPainterPath&) override {}
  void drawRects(const QRectF*, int) override {}
  void drawRects(const QRect*, int) override {}
  void drawLines(const QLineF*, int) override {}
  void drawLines(const QLine*, int) override {}
  void drawEllipse(const QRectF&) override {}
  void drawPoints(const QPointF*, int) override {}

  std::vector<PaintedText> texts;

 private:
  QTransform transform_;
};

class TextRecordingDevice final : public QPaintDevice {
 public:
  explicit TextRecordingDevice(const QSize& size) : size_(size) {}
  QPaintEngine* paintEngine() const override { return &engine_; }
  std::vector<PaintedText>& texts() { return engine_.texts; }

 protected:
  int metric(PaintDeviceMetric metric) const override {
    switch (metric) {
      case PdmWidth:
        return size_.width();
      case PdmHeight:
        return size_.height();
      case PdmDepth:
        return 32;
      case PdmNumColors:
        return 0x7fffffff;
      case PdmDpiX:
      case PdmDpiY:
      case PdmPhysicalDpiX:
      case PdmPhysicalDpiY:
        return 96;  // as a QImage has by default, so fonts in pixels measure alike
      case PdmDevicePixelRatio:
        return 1;
      case PdmDevicePixelRatioScaled:
        return int(devicePixelRatioFScale());
      default:  // widthMM, heightMM
        return metric == PdmWidthMM ? size_.width() * 254 / 960 : size_.height() * 254 / 960;
    }
  }

 private:
  QSize size_;
  mutable TextRecordingEngine engine_;
};

}  // namespace

std::vector<PaintedText> record_painted_text(const QSize& size,
                                             const std::function<void(QPainter&)>& paint) {
  TextRecordingDevice device(size);
  {
    QPainter painter(&device);
    paint(painter);
  }
  return std::move(device.texts());
}

namespace {
constexpr double kSliverPx = 1.5;
}  // namespace

std::vector<QString> text_problems(const std::vector<PaintedText>& texts, const QSize& size,
                                   double overlap_px2) {
  std::vector<QString> problems;
  const QRectF canvas = QRectF(QPointF(0, 0), QSizeF(size)).adjusted(-1, -1, 1, 1);
  for (size_t i = 0; i < texts.size(); ++i) {
    const PaintedText& t = texts[i];
    if (t.text.contains(kEllipsis))
      problems.push_back(QStringLiteral("elided: \"%1\"").arg(t.text));
    if (!canvas.contains(t.box)) {
      problems.push_back(QStringLiteral("\"%1\" leaves the canvas").arg(t.text));
    }
    for (size_t j = i + 1; j < texts.size(); ++j) {
      const QRectF both = t.box.intersected(texts[j].box);
      // Lines of one wrapped text sit a line spacing apart, which is a pixel less than their
      // boxes (ascent + descent) in fonts with a negative leading: a sliver of at most 1.5 px
      // is not an overlap anyone sees.
      if (both.width() * both.height() > overlap_px2 &&
          std::min(both.width(), both.height()) > kSliverPx) {
        problems.push_back(QStringLiteral("\"%1\" overlaps \"%2\"").arg(t.text, texts[j].text));
      }
    }
  }
  return problems;
}

}  // namespace oflab
