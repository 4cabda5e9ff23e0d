"""The flow of a tilted, moving plane: its eight coefficients, the flow field as a numpy
array, and the two planes and motions that make the same coefficients."""
import sys  # noqa: F401  (the examples take --quick; this one is quick anyway)
import numpy as np
import oflab

flow = oflab.flow(focal=500, image=[640, 480], plane_point=[0, 0, 10], plane_normal=[0.3, 0, -1],
                  velocity=[0.2, 0, 0.5], omega=[0, 0.05, 0], dt=1.0)
print("coefficients:", {k: round(v, 6) for k, v in flow["coefficients"].items()})
speed = np.linalg.norm(flow["field"], axis=2)
print(f"flow field {flow['field'].shape}: speed {speed.min():.2f} .. {speed.max():.2f} px per unit time")
print("exact homography over dt = 1:\n", np.round(flow["homography_exact"], 6))
for k, s in enumerate(oflab.explain(flow)["solutions"], 1):
    print(f"solution {k}: normal {np.round(s['normal'], 4)}, V/d {np.round(s['v_over_d'], 4)}, "
          f"omega {np.round(s['omega'], 4)}")
