"""Every reuse policy on the rotation script: work saved and measured error per policy,
and each policy's per-frame error as a numpy column."""
import sys
import oflab

quick = dict(frames=30, repeat_timing=1) if "--quick" in sys.argv else {}
names = [p["name"] for p in oflab.policies() if not p["scenes_only"]]  # the others need a scene
comparison = oflab.compare("rotation", names, **quick)
for row in comparison.summary["policies"]:
    errors = comparison.records[row["name"]]["measured_error_px"]
    print(f"{row['name']:20} work saved {100 * row['work_saved']:6.1f}%  "
          f"max error {row['max_measured_error_px']:6.3f} px  (per frame: {errors.size} values)")
