#include "analysis/experiments_scenes.h"

namespace oflab {

ReportSection experiment2_section(ExperimentContext& context) {
  context.progress("exp2", "not included in this build");
  ReportSection s;
  s.id = "experiment-2";
  s.title = "Experiment 2: many planes (sections 6.6, 6.7) - not included";
  s.paragraph(
      "Experiment 2 needs the multi-plane engine (scenes, BSP ordering, the scene animator), "
      "which this build of oflab does not contain yet. No figures are reported for it: the "
      "published ones (four cubes, compound script: polygons per level 33.0% none, 9.7% "
      "translate, 19.5% affine, 9.5% perspective, 28.3% re-render) have nothing to be compared "
      "with here.");
  return s;
}

}  // namespace oflab
