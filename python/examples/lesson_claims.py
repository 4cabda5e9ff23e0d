"""The lessons and the engine claims of one of them, checked headlessly."""
import sys
import oflab

for lesson in oflab.lessons():
    print(f"{lesson['order']:3} {lesson['name']:28} {len(lesson['steps']):2} steps, {lesson['claims']} claims")
name = "flow-of-a-plane"
checks = oflab.lesson(name).check()
print(f"{name}: {sum(c['holds'] for c in checks)} of {len(checks)} engine claims hold")
if "--quick" not in sys.argv:
    for c in checks:
        print(" ", c["text"])
