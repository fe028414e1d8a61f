#!/usr/bin/env python3
# Usage: python3 tests/benchmarks/build/pch_cpu_time.py N BUILD_DIR  (a build configured with WEARLINK_PCH=ON and built once)
# CPU time (user+sys) of compiling a sample of wearlink_lib's sources with and without
# the precompiled header, one compile at a time, alternating (robust to other load).
import json, os, re, resource, subprocess, sys, time
cc = json.load(open(sys.argv[2] + '/compile_commands.json'))
lib = [c for c in cc if '/src/' in c['file'] and 'CMakeFiles/wearlink_lib.dir' in c['command'] and 'cmake_pch' not in c['file']]
sample = lib[::max(1, len(lib)//int(sys.argv[1]))]
def cpu(cmd, directory):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, shell=True, check=True, cwd=directory, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
tot_on = tot_off = 0
for c in sample:
    cmd = c['command']
    on = re.sub(r' -o \S+', ' -o /tmp/pch_probe.o', cmd)
    off = re.sub(r'-Winvalid-pch ', '', re.sub(r' -include \S+cmake_pch.hxx', '', on))
    t_on = cpu(on, c['directory']); t_off = cpu(off, c['directory'])
    tot_on += t_on; tot_off += t_off
    print(f"{os.path.basename(c['file']):40s} pch {t_on:6.1f} s   no pch {t_off:6.1f} s")
print(f"sample of {len(sample)} of {len(lib)} sources: with pch {tot_on:.1f} s CPU, without {tot_off:.1f} s, ratio {tot_on/tot_off:.2f}")
