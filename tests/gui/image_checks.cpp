#include "image_checks.h"

#include <gtest/gtest.h>

#include <QDir>
#include <cmath>
#include <limits>
#include <set>

namespace oflab::test {

QImage scaled_rgb(const QImage& image, const QSize& size) {
  return image.convertToFormat(QImage::Format_RGB32)
      .scaled(size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
}

double psnr_db(const QImage& a, const QImage& b) {
  const QImage x = a.convertToFormat(QImage::Format_RGB32);
  const QImage y = b.convertToFormat(QImage::Format_RGB32);
  if (x.size() != y.size() || x.isNull()) return 0.0;
  double sum = 0.0;
  for (int row = 0; row < x.height(); ++row) {
    const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(row));
    const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(row));
    for (int col = 0; col < x.width(); ++col) {
      const double dr = qRed(p[col]) - qRed(q[col]), dg = qGreen(p[col]) - qGreen(q[col]),
                   db = qBlue(p[col]) - qBlue(q[col]);
      sum += dr * dr + dg * dg + db * db;
    }
  }
  const double mse = sum / (3.0 * x.width() * x.height());
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

int distinct_colours(const QImage& image) {
  const QImage x = image.convertToFormat(QImage::Format_RGB32);
  std::set<QRgb> colours;
  for (int row = 0; row < x.height(); ++row) {
    const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(row));
    for (int col = 0; col < x.width(); ++col) colours.insert(p[col] & 0xffffff);
  }
  return static_cast<int>(colours.size());
}

double changed_fraction(const QImage& a, const QImage& b, int threshold) {
  const QImage x = a.convertToFormat(QImage::Format_RGB32);
  const QImage y = b.convertToFormat(QImage::Format_RGB32);
  if (x.size() != y.size() || x.isNull()) return 1.0;
  long changed = 0;
  for (int row = 0; row < x.height(); ++row) {
    const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(row));
    const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(row));
    for (int col = 0; col < x.width(); ++col) {
      if (std::abs(qRed(p[col]) - qRed(q[col])) > threshold ||
          std::abs(qGreen(p[col]) - qGreen(q[col])) > threshold ||
          std::abs(qBlue(p[col]) - qBlue(q[col])) > threshold) {
        ++changed;
      }
    }
  }
  return static_cast<double>(changed) / (static_cast<double>(x.width()) * x.height());
}

QString output_dir() {
  const QString dir = QStringLiteral(OFLAB_GUI_TEST_OUTPUT);
  QDir().mkpath(dir);
  return dir;
}

FrameAgreement agreement_writing_failures(const Image& a, const Image& b, double min_iou,
                                          double min_psnr_db, const QString& name,
                                          const QString& label_a, const QString& label_b) {
  const FrameAgreement agreement = frame_agreement(a, b);
  if (agreement.mask_iou < min_iou || agreement.psnr_db < min_psnr_db) {
    flatten_image(a, Qt::black).save(output_dir() + "/" + name + "-" + label_a + ".png");
    flatten_image(b, Qt::black).save(output_dir() + "/" + name + "-" + label_b + ".png");
  }
  return agreement;
}

void expect_matches_baseline(const QImage& rendered, const QString& name, int width) {
  ASSERT_FALSE(rendered.isNull());
  const QString path = QStringLiteral(OFLAB_GUI_BASELINES "/%1.png").arg(name);
  const QSize size(width, width * rendered.height() / rendered.width());
  if (qEnvironmentVariableIsSet("OFLAB_UPDATE_BASELINES")) {
    ASSERT_TRUE(scaled_rgb(rendered, size).save(path, "PNG"));
    GTEST_SKIP() << "baseline rewritten: " << path.toStdString();
  }
  const QString actual_path = output_dir() + "/" + name + "-actual.png";
  const QImage baseline(path);
  if (baseline.isNull()) {
    scaled_rgb(rendered, size).save(actual_path, "PNG");
    FAIL() << "missing baseline " << path.toStdString() << "; rendered image written to "
           << actual_path.toStdString();
  }
  const double psnr = psnr_db(baseline, scaled_rgb(rendered, baseline.size()));
  if (psnr < kBaselinePsnrDb) scaled_rgb(rendered, baseline.size()).save(actual_path, "PNG");
  EXPECT_GE(psnr, kBaselinePsnrDb) << name.toStdString() << " differs from its baseline; "
                                   << "rendered image written to " << actual_path.toStdString();
}

}  // namespace oflab::test
