#!/usr/bin/env python3
"""The web page's speed, in Debian's headless Chromium on SwiftShader at 1280x720, beside
the native build in the same run:

- compute: each lab's whole report at its defaults, timed in WebAssembly inside the page
  (Page.computeSeconds) and natively (import rigidlab's _compute_seconds: the same
  session_at in a loop); the ratio of the medians. Goal: at most 2.
- first frame: from navigation to the first frame drawn, the page reloaded with a warm
  cache (median of 5). Goal: 2 s.
- frames: the interval between frames while each lab's motion plays (median, p95).
  Goal: 30 fps, a p95 of 33.3 ms.
- input: a number typed in a field to the frame that shows it (and to the whole report's
  frame, where a lab computes a preview first), p95. Goal: 100 ms.
- download: what the page fetches, gzip -9 as a server compresses it. Goal: 6 MB.

Usage: web_bench.py --site build/web --modules build/web-test/node_modules --out FILE
(PYTHONPATH at the build's python/). Writes a JSON array of entries {"group": "web", ...}.
"""
import argparse
import gzip
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "web"))
from check import serve  # noqa: E402  the test's static server


def p95(values):
    return sorted(values)[min(len(values) - 1, int(0.95 * len(values)))] if values else 0.0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--site", required=True)
    parser.add_argument("--modules", required=True)
    parser.add_argument("--out", required=True)
    a = parser.parse_args()
    import rigidlab as rl

    server, base = serve(a.site)
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "bench.json")
        subprocess.run(["node", os.path.join(HERE, "..", "tests", "web", "browse.js"), base,
                        "bench", out], check=True, env=dict(os.environ, NODE_PATH=a.modules))
        measured = json.load(open(out))
    server.shutdown()

    entries = []
    for lab, m in measured["labs"].items():
        wasm = m["compute_s"]
        native = rl._rigidlab._compute_seconds(lab, [], len(wasm))
        entries.append({"group": "web", "kind": "compute", "case": lab,
                        "seconds": statistics.median(wasm), "p95": p95(wasm),
                        "native_seconds": statistics.median(native), "native_p95": p95(native),
                        "least_seconds": min(wasm), "native_least_seconds": min(native),
                        "repeats": len(wasm)})
        frames = m["frame_interval_ms"]
        entries.append({"group": "web", "kind": "interaction", "case": lab, "input": m["input"],
                        "frame_median_ms": statistics.median(frames) if frames else None,
                        "frame_p95_ms": p95(frames) if frames else None,
                        "input_to_frame_p95_ms": p95(m["input_to_frame_ms"]),
                        "input_to_frame_median_ms": statistics.median(m["input_to_frame_ms"] or [0]),
                        "input_to_whole_p95_ms": p95(m["input_to_whole_ms"]),
                        "first_input_ms": (m["first_input_ms"] or [0])[0]})
    sizes = {}
    for name in sorted(os.listdir(a.site)):
        with open(os.path.join(a.site, name), "rb") as f:
            sizes[name] = len(gzip.compress(f.read(), 9))
    entries.append({"group": "web", "kind": "page", "case": "the page",
                    "first_frame_ms": statistics.median(measured["first_frame_ms"]),
                    "first_frame_all_ms": measured["first_frame_ms"],
                    "download_bytes": sum(sizes.values()), "files": sizes,
                    "problems": measured["problems"]})
    with open(a.out, "w") as f:
        json.dump(entries, f, indent=1)

    print("| lab | compute() wasm | native | ratio | least's ratio | frames median / p95 "
          "| input to frame p95 | to the whole report p95 | the first input |"
          "\n|---|---|---|---|---|---|---|---|---|")
    for c, i in zip(entries[0::2], entries[1::2]):
        frames = (f"{i['frame_median_ms']:.1f} / {i['frame_p95_ms']:.1f} ms"
                  if i["frame_median_ms"] is not None else "no motion")
        print(f"| {c['case']} | {c['seconds'] * 1e3:.3f} ms | {c['native_seconds'] * 1e3:.3f} ms "
              f"| {c['seconds'] / c['native_seconds']:.2f} "
              f"| {c['least_seconds'] / c['native_least_seconds']:.2f} | {frames} | "
              f"{i['input_to_frame_p95_ms']:.0f} ms | {i['input_to_whole_p95_ms']:.0f} ms | "
              f"{i['first_input_ms']:.0f} ms |")
    page = entries[-1]
    print(f"\nfirst frame {page['first_frame_ms']:.0f} ms (warm cache, median of 5); "
          f"download {page['download_bytes'] / 1e6:.2f} MB gzip -9 {page['files']}")


if __name__ == "__main__":
    main()
