#include "generators/fabric_texture.h"

#include "generators/butterfly.h"
#include "image/composite.h"

namespace oflab {

Image make_fabric_texture() {
  constexpr int kWidth = 512;
  constexpr int kHeight = 416;
  constexpr int kCell = 2;  // texels per chequer cell
  Image fabric(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const bool light = ((x / kCell) + (y / kCell)) % 2 == 0;
      fabric.at(x, y) = light ? Pixel{236, 226, 200, 255} : Pixel{60, 70, 110, 255};
    }
  }
  // The butterfly, centred; its transparent background shows the ground.
  const Image butterfly = make_butterfly(384, 312);
  const int ox = (kWidth - butterfly.width()) / 2, oy = (kHeight - butterfly.height()) / 2;
  for (int y = 0; y < butterfly.height(); ++y) {
    for (int x = 0; x < butterfly.width(); ++x) {
      fabric.at(ox + x, oy + y) = over(butterfly.at(x, y), fabric.at(ox + x, oy + y));
    }
  }
  return fabric;
}

}  // namespace oflab
