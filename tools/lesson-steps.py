#!/usr/bin/env python3
# Writes the "Step by step" block of each lesson section of manual/lessons.md from the lesson
# files (datasets/lessons/*.json): each step's caption and its picture, which
# tools/make-screenshots.sh makes with oflab --check-lesson --step-shots. Run from the root.
import json, glob, re
p='manual/lessons.md'; s=open(p).read()
for f in sorted(glob.glob("datasets/lessons/*.json")):
    d=json.load(open(f)); steps=d.get("steps",[])
    name=d["name"]
    head=re.search(r"^## .* \(`%s`\)\s*$" % re.escape(name), s, re.M)
    if not head: continue
    start=head.end()
    nxt=re.search(r"^## ", s[start:], re.M)
    end=start+(nxt.start() if nxt else len(s)-start)
    section=s[start:end]
    section=re.sub(r"\n<!-- steps -->.*?<!-- /steps -->\n", "\n", section, flags=re.S)
    if steps:
        block="\n<!-- steps -->\nStep by step (each picture is the window after the check measured that step's claims):\n\n"
        for k,st in enumerate(steps,1):
            block+="%d. %s\n\n   ![%s, step %d](images/lesson-%s-step-%d.png)\n\n" % (k, st["say"], d["title"], k, name, k)
        block+="<!-- /steps -->\n"
        section=section.rstrip("\n")+"\n"+block+"\n"
    s=s[:start]+section+s[end:]
open(p,'w').write(s)
