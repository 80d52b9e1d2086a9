"""Allocation sites of one trajeval run (called by bench/alloc-sites.sh): JFR's
jdk.ObjectAllocationOutsideTLAB and jdk.ObjectAllocationInNewTLAB events (objects of at least
64 KiB: a large array may also open a TLAB of its own in the young generation) grouped by the first org.trajeval frame and its caller,
as markdown rows (MiB, arrays, share of the total), with the run's peak RSS and minor page faults.

usage: alloc_sites.py EVENTS.json TIME_FILE MIN_MIB   (TIME_FILE: /usr/bin/time -f '%M %R %e %U %S')
"""
import json
import sys
from collections import defaultdict

MIB = 1024.0 * 1024.0


def cls(frame):
    return frame["method"]["type"]["name"].replace("/", ".")


def site(frames):
    """The first frame of trajeval's code, 'Class.method:line', and its caller's method."""
    names = [f"{cls(f).rsplit('.', 1)[-1]}.{f['method']['name']}:{f.get('lineNumber', '?')}"
             for f in frames if cls(f).startswith("org.trajeval")]
    if not names:
        top = frames[0]["method"] if frames else None
        return "JDK: " + (f"{cls(frames[0])}.{top['name']}" if top else "?")
    return names[0] + (" <- " + names[1].split(":")[0] if len(names) > 1 else "")


def main():
    events = json.load(open(sys.argv[1]))["recording"]["events"]
    peak_kb, minor_faults, wall, user, sys_s = open(sys.argv[2]).read().split()
    min_mib = float(sys.argv[3])
    by_site = defaultdict(lambda: [0, 0])
    for e in events:
        v = e["values"]
        if v["allocationSize"] < 65536:
            continue
        key = site((v.get("stackTrace") or {}).get("frames", []))
        by_site[key][0] += 1
        by_site[key][1] += v["allocationSize"]
    total = sum(b for _, b in by_site.values())
    print("| allocation site (first trajeval frame <- caller) | arrays | MiB | share |")
    print("| --- | ---: | ---: | ---: |")
    rest = [0, 0]
    for key, (count, size) in sorted(by_site.items(), key=lambda kv: -kv[1][1]):
        if size / MIB >= min_mib:
            print(f"| {key} | {count} | {size / MIB:.1f} | {100.0 * size / total:.1f} % |")
        else:
            rest[0] += count
            rest[1] += size
    if rest[0]:
        print(f"| (sites under {min_mib:g} MiB) | {rest[0]} | {rest[1] / MIB:.1f} | {100.0 * rest[1] / total:.1f} % |")
    print(f"\nallocated in objects of 64 KiB or more: {total / MIB:.0f} MiB ({total / 4096:.0f} pages of 4 KiB); "
          f"peak RSS {int(peak_kb) / 1024:.0f} MiB; minor page faults {minor_faults} "
          f"({int(minor_faults) * 4096 / MIB:.0f} MiB at 4 KiB); wall {wall} s, user {user} s, sys {sys_s} s (with JFR on)")


if __name__ == "__main__":
    main()
