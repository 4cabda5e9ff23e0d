#include "image/image_compare.h"

#include <cmath>
#include <stdexcept>

namespace oflab {

double psnr_db(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) {
    throw std::invalid_argument("psnr_db: images differ in size");
  }
  double sum = 0.0;
  std::size_t count = 0;
  const auto& pa = a.pixels();
  const auto& pb = b.pixels();
  for (std::size_t i = 0; i < pa.size(); ++i) {
    if (pa[i].a == 0 && pb[i].a == 0) continue;
    const double dr = pa[i].r - pb[i].r, dg = pa[i].g - pb[i].g, db = pa[i].b - pb[i].b,
                 da = pa[i].a - pb[i].a;
    sum += dr * dr + dg * dg + db * db + da * da;
    count += 4;
  }
  if (count == 0 || sum == 0.0) return kIdenticalPsnrDb;
  const double mse = sum / static_cast<double>(count);
  return std::min(kIdenticalPsnrDb, 10.0 * std::log10(255.0 * 255.0 / mse));
}

}  // namespace oflab
