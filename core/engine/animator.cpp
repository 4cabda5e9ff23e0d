// The shared frame report of every animator (see core/engine/animator.h).
#include "engine/animator.h"

namespace oflab {

int AnimationFrame::drawn() const {
  int n = 0;
  for (int c : levels) n += c;
  return n;
}

}  // namespace oflab
