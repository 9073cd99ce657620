#!/usr/bin/env python3
"""A league of seeded matches in the sim, each a Ray task (Tools/match/match.sh, refereed), and a table.

    Tools/match/league.py [--matches 20] [--per-team 2] [--half 60] [--ready 45] [--seed 1]
                  [--alone alternate|none|1|2] [--address ADDR] [--cpus-per-match 2]
                  [--id-base 133000] [--json FILE]

Ray runs on this machine by default (ray.init() starts it and shuts it down at the end); with
--address (e.g. ray://head:10001 or head:6379) the same tasks go to that cluster, no code change.
Each node needs this repository built at the same path (or --root). Every match has its own
ROBOT_ID block (shm segments and UDP ports derive from it: --id-base + 4 * per-team * k for the
k-th match),
so matches can share a node.

--alone says which team plays without team play (team messages and roles off: game.lua's
team.enabled, roles.enabled): 'alternate' gives team 2 to odd seeds and team 1 to even ones (each
side of the comparison kicks off first as often); 'us' is then the team WITH team play.

Prints one row per match and the totals: goals for and against, own goals, falls (the referee's count, by the
fall census's definition: one per lying, Tools/match/census.lua), penalties, seconds
in each role, seconds with a mirrored pose belief (Tools/match/tally.lua), from 'us' (team 1 when
--alone none).
"""
import argparse
import json
import os
import re
import secrets
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ROLES = ("striker", "supporter", "defender", "goalkeeper")


def play(root, robot_id, per_team, half, ready, seed, alone):
    """One match (runs on a Ray worker): match.sh's output and exit status."""
    env = dict(os.environ, ROBOT_ID=str(robot_id), ALONE=" ".join(str(t) for t in alone))
    cmd = ["nice", "bash", os.path.join(root, "Tools/match/match.sh"), str(per_team), str(half), str(seed),
           str(ready)]
    t0 = time.time()
    # its own process group (a cancelled task ends the whole match), and one shell in between: when the
    # worker exits, Ray kills its direct children with SIGKILL (RAY_kill_child_processes_on_worker_exit),
    # which would leave match.sh no time to clean up. With the shell in between, match.sh outlives the
    # worker, sees its parent gone and ends the match itself (its processes, its shared memory).
    p = subprocess.Popen(["bash", "-c", '"$@" & wait $!', "play"] + cmd, env=env, cwd=root,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        out, _ = p.communicate()
    except BaseException:
        end_group(p)
        raise
    return {"seed": seed, "robot_id": robot_id, "rc": p.returncode, "wall": time.time() - t0, "output": out}


def end_group(proc, grace=15.0):
    """SIGTERM to the process group that `proc` leads (a match), then time for match.sh's cleanup;
    SIGKILL after `grace` s."""
    pgid = proc.pid
    try:
        os.killpg(pgid, signal.SIGTERM)
        deadline = time.time() + grace
        while time.time() < deadline:
            time.sleep(0.2)
            proc.poll()  # reaps the leader: a zombie still counts as a member
            os.killpg(pgid, 0)  # ProcessLookupError once the group is empty
        os.killpg(pgid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def parse(out):
    """The referee's closing lines (Tools/match/referee.lua) as numbers; None when the match did not finish."""
    m = re.search(r"^result: team (\d+) (\d+) : (\d+) team (\d+)$", out, re.M)
    if not m:
        return None
    r = {"teams": {}, "robots": {}}
    for t, g, og, f, p in re.findall(r"^team (\d+): goals (\d+), own goals (\d+), falls (\d+), penalties (\d+)$",
                                     out, re.M):
        r["teams"][int(t)] = {"goals": int(g), "own_goals": int(og), "falls": int(f), "penalties": int(p)}
    for team, player, rest in re.findall(r"^tally (\d+)/(\d+) (.*)$", out, re.M):
        r["robots"]["%s/%s" % (team, player)] = {k: float(v) for k, v in re.findall(r"(\w+)=([\d.]+)", rest)}
    m = re.search(r"real-time factor ([\d.]+)", out)
    r["rtf"] = float(m.group(1)) if m else None
    return r


def alone_for(mode, seed):
    if mode == "none":
        return []
    if mode == "alternate":
        return [2 if seed % 2 else 1]
    return [int(mode)]


def row(res, us):
    """The figures of one finished match from team `us`'s side."""
    them = 3 - us
    r = res["parsed"]
    a, b = r["teams"][us], r["teams"][them]
    # the opponents' own goals are goals for us, and the referee counts them as ours already
    out = {"seed": res["seed"], "us": us, "for": a["goals"], "against": b["goals"], "own_us": a["own_goals"],
           "own_them": b["own_goals"], "falls_us": a["falls"], "falls_them": b["falls"],
           "pen_us": a["penalties"], "pen_them": b["penalties"], "wall": res["wall"], "rtf": r["rtf"]}
    for name in ROLES + ("mirrored",):
        out[name] = sum(v.get(name, 0) for k, v in r["robots"].items() if k.startswith("%d/" % us))
        out[name + "_them"] = sum(v.get(name, 0) for k, v in r["robots"].items() if k.startswith("%d/" % them))
    return out


def print_table(rows, failed, args):
    head = ("seed us  for agst  own(us/them)  falls(us/them)  pen(us/them)  striker suppor defend goalkp"
            "  mirrored(us/them) s   wall s")
    print(head)
    for x in rows:
        print("%4d %2d  %3d %4d  %5d/%-5d  %7d/%-6d  %6d/%-5d  %7.0f %6.0f %6.0f %6.0f  %8.1f/%-8.1f  %6.0f" % (
            x["seed"], x["us"], x["for"], x["against"], x["own_us"], x["own_them"], x["falls_us"], x["falls_them"],
            x["pen_us"], x["pen_them"], x["striker"], x["supporter"], x["defender"], x["goalkeeper"],
            x["mirrored"], x["mirrored_them"], x["wall"]))
    if rows:
        tot = {k: sum(x[k] for x in rows) for k in rows[0] if k not in ("seed", "us", "rtf")}
        won = sum(1 for x in rows if x["for"] > x["against"])
        lost = sum(1 for x in rows if x["for"] < x["against"])
        print("total %d matches (2 x %g s, %d v %d, team play off for: %s): goals for %d, against %d; won %d, drawn %d,"
              " lost %d; own goals us %d, them %d; falls %d/%d; penalties %d/%d; mirrored belief %.1f/%.1f s" % (
                  len(rows), args.half, args.per_team, args.per_team, args.alone, tot["for"], tot["against"], won,
                  len(rows) - won - lost, lost, tot["own_us"], tot["own_them"], tot["falls_us"], tot["falls_them"],
                  tot["pen_us"], tot["pen_them"], tot["mirrored"], tot["mirrored_them"]))
        print("time in each role (us, s): " + ", ".join("%s %.0f" % (k, tot[k]) for k in ROLES))
    for f in failed:
        print("match seed %d (ROBOT_ID %d) did not finish (exit %d): last lines:\n%s" % (
            f["seed"], f["robot_id"], f["rc"], "\n".join(f["output"].splitlines()[-8:])))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--matches", type=int, default=20)
    ap.add_argument("--per-team", type=int, default=2)
    ap.add_argument("--half", type=float, default=60, help="s of PLAYING per half (simulated)")
    ap.add_argument("--ready", type=float, default=45,
                    help="s of READY (simulated): the rules' 45, in which a goalkeeper walks from the touch line to its goal")
    ap.add_argument("--seed", type=int, default=1, help="the first match's seed (then seed + 1, ...)")
    ap.add_argument("--alone", default="alternate", choices=("alternate", "none", "1", "2"))
    ap.add_argument("--address", default=None, help="a Ray cluster's address (default: Ray on this machine)")
    ap.add_argument("--cpus-per-match", type=float, default=2.0,
                    help="Ray CPUs a match takes (2 on this 2-core machine: one match at a time)")
    ap.add_argument("--id-base", type=int, default=int(os.environ.get("ROBOT_ID", "133000")))
    ap.add_argument("--root", default=ROOT, help="the repository's path on the nodes")
    ap.add_argument("--json", default=None, help="write the per-match results here")
    ap.add_argument("--tabulate", nargs="+", metavar="REFEREE_LOG",
                    help="no matches: the table of finished matches' referee logs (build/match/<id>/referee.log;"
                         " their seeds from --seed on, in the order given)")
    args = ap.parse_args()
    if args.matches < 1 or args.per_team < 1 or args.half <= 0 or args.ready <= 0:
        ap.error("--matches, --per-team, --half and --ready must be positive")

    if args.tabulate:
        results = []
        for k, path in enumerate(args.tabulate):
            with open(path) as f:
                out = f.read()
            results.append({"seed": args.seed + k, "robot_id": 0, "rc": 0, "wall": 0, "output": out,
                            "parsed": parse(out)})
        return report(results, args)

    if not args.address:
        # Ray's token authentication stays on, with a token made for this run and held in the
        # environment (its workers inherit it): nothing is written outside the repository (~/.ray)
        os.environ.setdefault("RAY_AUTH_MODE", "token")
        os.environ.setdefault("RAY_AUTH_TOKEN", secrets.token_hex(32))
    import ray  # late: --help works without it
    if args.address:
        ray.init(address=args.address, log_to_driver=False)
    else:
        # a small object store (results are a few kB; the default takes 30% of memory in /dev/shm),
        # no dashboard: a shared 2-core machine; Ray's session files under build/ray
        ray.init(num_cpus=os.cpu_count(), object_store_memory=80 * 1024 * 1024, include_dashboard=False,
                 log_to_driver=False, _temp_dir=os.path.join(args.root, "build", "ray"))
    # SIGTERM as Ctrl-C: the tasks are cancelled (each ends its match) and Ray shut down
    signal.signal(signal.SIGTERM, lambda *_: (_ for _ in ()).throw(KeyboardInterrupt()))
    refs = []
    try:
        task = ray.remote(num_cpus=args.cpus_per_match)(play)
        stride = 2 * args.per_team * 2  # robot ids per match (match.sh: 2 * per_team), with room
        for k in range(args.matches):
            seed = args.seed + k
            refs.append(task.remote(args.root, args.id_base + stride * k, args.per_team, args.half, args.ready,
                                    seed, alone_for(args.alone, seed)))
        results = []
        pending = list(refs)
        while pending:
            done, pending = ray.wait(pending, num_returns=1)
            res = ray.get(done[0])
            res["parsed"] = parse(res["output"]) if res["rc"] == 0 else None
            results.append(res)
            sys.stderr.write("league: seed %d done in %.0f s (exit %d), %d left\n" % (
                res["seed"], res["wall"], res["rc"], len(pending)))
    except KeyboardInterrupt:
        sys.stderr.write("league: interrupted, cancelling the matches\n")
        for r in refs:
            try:
                ray.cancel(r)
            except Exception:  # finished already, or Ray going down
                pass
        time.sleep(3)
        raise
    finally:
        ray.shutdown()
    return report(results, args)


def report(results, args):
    """The table of the finished matches; 1 if any did not finish."""
    results.sort(key=lambda r: r["seed"])
    rows, failed = [], []
    for res in results:
        if res["parsed"]:
            alone = alone_for(args.alone, res["seed"])
            us = (3 - alone[0]) if alone else 1
            rows.append(row(res, us))
        else:
            failed.append(res)
    print_table(rows, failed, args)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"args": vars(args), "rows": rows,
                       "failed": [{k: v for k, v in x.items() if k != "parsed"} for x in failed]}, f, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except KeyboardInterrupt:
        sys.exit(130)
