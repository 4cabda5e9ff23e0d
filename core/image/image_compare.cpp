#include "image/image_compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace oflab {

double psnr_db(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) {
    throw std::invalid_argument("psnr_db: images differ in size");
  }
  if (&a == &b) return kIdenticalPsnrDb;  // an image against itself: no channel differs
  // Whole-number tallies, exact (a pixel adds at most 4 x 255^2; a frame's sum stays far
  // below 2^53, so it is the sum a double would give), and without branches, so that the
  // compiler vectorises the rows: a pixel transparent in both images adds 0 to both.
  std::int64_t sum = 0, covered = 0;
  for (int y = 0; y < a.height(); ++y) {
    const Pixel* pa = a.row(y);
    const Pixel* pb = b.row(y);
    std::int64_t row_sum = 0, row_covered = 0;
    for (int x = 0; x < a.width(); ++x) {
      const int any = (pa[x].a | pb[x].a) != 0;
      const int dr = pa[x].r - pb[x].r, dg = pa[x].g - pb[x].g, db = pa[x].b - pb[x].b,
                da = pa[x].a - pb[x].a;
      row_sum += any * (dr * dr + dg * dg + db * db + da * da);
      row_covered += any;
    }
    sum += row_sum;
    covered += row_covered;
  }
  if (covered == 0 || sum == 0) return kIdenticalPsnrDb;
  const double mse = static_cast<double>(sum) / static_cast<double>(4 * covered);
  return std::min(kIdenticalPsnrDb, 10.0 * std::log10(255.0 * 255.0 / mse));
}

namespace {

// The normalised 1-D Gaussian of the SSIM window; its outer product is the 2-D window.
std::array<double, kSsimWindow> ssim_weights() {
  std::array<double, kSsimWindow> w{};
  double sum = 0.0;
  for (int k = 0; k < kSsimWindow; ++k) {
    const double x = k - (kSsimWindow - 1) / 2.0;
    w[k] = std::exp(-x * x / (2.0 * kSsimSigma * kSsimSigma));
    sum += w[k];
  }
  for (double& v : w) v /= sum;
  return w;
}

void luma(const Image& image, std::vector<double>& y) {
  y.resize(image.pixel_count());
  for (std::size_t k = 0; k < y.size(); ++k) {
    const Pixel p = image.pixels()[k];
    y[k] = 0.299 * p.r + 0.587 * p.g + 0.114 * p.b;
  }
}

// The "valid" Gaussian filtering of `v` (width x height) into `out`: rows (into `rows`),
// then columns. Every element of both is written.
void filtered(const std::vector<double>& v, int width, int height, std::vector<double>& rows,
              std::vector<double>& out) {
  static const std::array<double, kSsimWindow> w = ssim_weights();
  const int ow = width - kSsimWindow + 1, oh = height - kSsimWindow + 1;
  rows.resize(static_cast<std::size_t>(ow) * height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k < kSsimWindow; ++k)
        s += w[k] * v[static_cast<std::size_t>(y) * width + x + k];
      rows[static_cast<std::size_t>(y) * ow + x] = s;
    }
  }
  out.resize(static_cast<std::size_t>(ow) * oh);
  for (int y = 0; y < oh; ++y) {
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k < kSsimWindow; ++k)
        s += w[k] * rows[static_cast<std::size_t>(y + k) * ow + x];
      out[static_cast<std::size_t>(y) * ow + x] = s;
    }
  }
}

// The working memory of mean_ssim, kept by each thread that measures: a frame's planes are
// megabytes each, and fresh ones cost a page fault per page every frame.
struct SsimScratch {
  std::vector<double> x, y, xx, yy, xy, rows, mx, my, sxx, syy, sxy;
};

}  // namespace

double mean_ssim(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) {
    throw std::invalid_argument("mean_ssim: images differ in size");
  }
  if (a.width() < kSsimWindow || a.height() < kSsimWindow) {
    throw std::invalid_argument("mean_ssim: images smaller than the 11 x 11 window");
  }
  const int w = a.width(), h = a.height();
  thread_local SsimScratch m;
  luma(a, m.x);
  luma(b, m.y);
  m.xx.resize(m.x.size());
  m.yy.resize(m.x.size());
  m.xy.resize(m.x.size());
  for (std::size_t k = 0; k < m.x.size(); ++k) {
    m.xx[k] = m.x[k] * m.x[k];
    m.yy[k] = m.y[k] * m.y[k];
    m.xy[k] = m.x[k] * m.y[k];
  }
  filtered(m.x, w, h, m.rows, m.mx);
  filtered(m.y, w, h, m.rows, m.my);
  filtered(m.xx, w, h, m.rows, m.sxx);
  filtered(m.yy, w, h, m.rows, m.syy);
  filtered(m.xy, w, h, m.rows, m.sxy);
  const std::vector<double>&mx = m.mx, &my = m.my, &sxx = m.sxx, &syy = m.syy, &sxy = m.sxy;
  const double c1 = (0.01 * 255.0) * (0.01 * 255.0), c2 = (0.03 * 255.0) * (0.03 * 255.0);
  double sum = 0.0;
  for (std::size_t k = 0; k < mx.size(); ++k) {
    const double vx = sxx[k] - mx[k] * mx[k], vy = syy[k] - my[k] * my[k];
    const double cov = sxy[k] - mx[k] * my[k];
    sum += (2.0 * mx[k] * my[k] + c1) * (2.0 * cov + c2) /
           ((mx[k] * mx[k] + my[k] * my[k] + c1) * (vx + vy + c2));
  }
  return sum / static_cast<double>(mx.size());
}

}  // namespace oflab
