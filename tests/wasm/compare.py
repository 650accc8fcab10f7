"""Compare two lab_report outputs (native and wasm): the same keys, texts and
notes, and every number within a few ulps (emscripten's libm is musl's, not
glibc's: sin, exp and the like may round their last bit differently)."""
import json
import math
import sys

ULPS = 64  # a result is at most a few dozen libm calls deep


def walk(a, b, path, worst):
    if isinstance(a, dict):
        assert isinstance(b, dict) and list(a) == list(b), f"{path}: keys differ"
        for k in a:
            walk(a[k], b[k], f"{path}.{k}", worst)
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), f"{path}: lengths differ"
        for i, (x, y) in enumerate(zip(a, b)):
            walk(x, y, f"{path}[{i}]", worst)
    elif isinstance(a, float) or isinstance(b, float):
        scale = max(abs(a), abs(b), sys.float_info.min)
        ulps = abs(a - b) / (scale * sys.float_info.epsilon)
        if ulps > worst[0]:
            worst[:] = [ulps, path]
        assert ulps <= ULPS, f"{path}: native {a!r} wasm {b!r} ({ulps:.0f} ulps)"
    else:
        assert a == b, f"{path}: native {a!r} wasm {b!r}"


native = json.load(open(sys.argv[1]))
wasm = json.load(open(sys.argv[2]))
worst = [0.0, ""]
walk(native, wasm, "", worst)
count = sum(len(v["results"]) for v in native.values())
print(f"wasm: {len(native)} reports, {count} results equal to the native run "
      f"(largest difference {worst[0]:.0f} ulps{' at ' + worst[1] if worst[1] else ''})")
