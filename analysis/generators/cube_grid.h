// The scale generator of Experiment 2: grids of open cubes (five faces each, bottom
// missing, as Fig. 25's cubes) to show how frame time grows with the number of polygons.
#pragma once

#include "scene/scene.h"

namespace oflab {

// `cubes` open cubes on a square grid in the plane Y = 0 of a Y-up world, centred at the
// origin, using texture 0 (the caller supplies it). The grid always spans the footprint of
// the four-cubes scene (3.5 x 3.5 units), so the shipped viewer scripts frame every grid
// alike: with k = ceil(sqrt(cubes)) columns the cubes have side 2 / k and their centres are
// 5 / k apart; k = 2 gives exactly the four-cubes layout. 5 * cubes polygons.
// Precondition: 1 <= cubes <= 20000 (throws std::invalid_argument otherwise).
Scene make_cube_grid(int cubes);

}  // namespace oflab
