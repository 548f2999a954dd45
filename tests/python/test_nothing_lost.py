"""Nothing lost (issue 8, item 5): an interrupted `hoct tree` or `hoct render` (SIGINT while
computing, SIGTERM while writing) leaves no partial or temporary file and an existing output file intact, and exits
with 128 + signal; the same input gives byte-identical JSON and VTP across runs and thread
counts."""
import os
import signal
import subprocess
import time

from hoct_testing import HOCT, Results, run, tempdir

R = Results()


def leftovers(d):
    return sorted(f for f in os.listdir(d) if ".tmp-" in f)


with tempdir() as tmp:
    p = lambda name: os.path.join(tmp, name)
    run("generate", "random", "--cells", "1e5", "-o", p("big.vtu"))
    old = "OLD CONTENT, must survive\n"

    def start(*extra):
        for name in ("out.json", "out.vtp"):
            with open(p(name), "w") as f:
                f.write(old)
        return subprocess.Popen([HOCT, "tree", p("big.vtu"), "--augmented", "-q", "--threads", "1",
                                 "--json", p("out.json"), "--vtp", p("out.vtp"), *extra],
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)

    def intact(name):
        return open(p(name)).read() == old

    # SIGINT while computing: on 2.5e5 cells `hoct tree` reports its phases on stderr, and the
    # signal goes when the first (the edge critical points) is done, before anything is written.
    # (A fixed delay raced with the writing once the tree and the JSON got faster.)
    run("generate", "random", "--cells", "2.5e5", "-o", p("bigger.vtu"))
    for name in ("out.json", "out.vtp"):
        with open(p(name), "w") as f:
            f.write(old)
    def interrupt_while_computing(sig, expected, name):
        proc = subprocess.Popen([HOCT, "tree", p("bigger.vtu"), "--threads", "1", "--json",
                                 p("out.json"), "--vtp", p("out.vtp")],
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        for line in proc.stderr:
            if "edge critical points" in line:
                break
        proc.send_signal(sig)
        proc.stderr.read()
        rc = proc.wait(60)
        R.check(rc == expected, f"{name} while computing: exit {rc} (expected {expected})")
        R.check(leftovers(tmp) == [], f"{name}: temporary files left: {leftovers(tmp)}")
        R.check(intact("out.json") and intact("out.vtp"), f"{name}: existing outputs intact")

    interrupt_while_computing(signal.SIGINT, 130, "SIGINT")
    # SIGQUIT (issue 27, item 5) as SIGINT: exit 131, nothing left behind.
    interrupt_while_computing(signal.SIGQUIT, 131, "SIGQUIT")

    # SIGTERM while writing: wait until the JSON's temporary file exists, then kill.
    def sigterm_while_writing(start_run, what):
        """Starts runs until one is caught with its temporary file present, sends SIGTERM, checks
        the exit status and that no temporary file is left; returns True if one was caught."""
        for attempt in range(5):
            proc = start_run()
            seen = False
            while proc.poll() is None:
                if leftovers(tmp):
                    proc.send_signal(signal.SIGTERM)
                    seen = True
                    break
                time.sleep(0.0005)
            rc = proc.wait(60)
            if not seen:
                continue  # finished writing between two looks: try again
            R.check(rc == 143, f"{what}, SIGTERM while writing: exit {rc} (expected 143)")
            R.check(leftovers(tmp) == [], f"{what} SIGTERM: temporary files left: {leftovers(tmp)}")
            return True
        R.check(False, f"{what}: never saw the temporary file while writing")
        return False

    if sigterm_while_writing(start, "tree"):
        # The JSON is written first; the VTP after it. Whatever was complete was renamed into
        # place whole; nothing is half written.
        js = open(p("out.json")).read()
        R.check(js == old or js.rstrip().endswith("}"), "SIGTERM: out.json old or complete")
        R.check(intact("out.vtp") or open(p("out.vtp")).read().rstrip().endswith("</VTKFile>"),
                "SIGTERM: out.vtp old or complete")

    # Uninterrupted, the same command writes both files completely.
    proc = start()
    R.check(proc.wait(120) == 0 and not intact("out.json") and leftovers(tmp) == [],
            "uninterrupted run writes its outputs")

    # `hoct render` interrupted: SIGINT while drawing, SIGTERM while writing the picture.
    def start_render(out, *extra):
        with open(p(out), "w") as f:
            f.write(old)
        return subprocess.Popen([HOCT, "render", p("big.vtu"), "-o", p(out), *extra],
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)

    proc = start_render("pic.png", "--isolines", "40")
    time.sleep(0.5)
    proc.send_signal(signal.SIGINT)
    rc = proc.wait(60)
    R.check(rc == 130, f"render, SIGINT while drawing: exit {rc} (expected 130)")
    R.check(leftovers(tmp) == [], f"render SIGINT: temporary files left: {leftovers(tmp)}")
    R.check(intact("pic.png"), "render SIGINT: the existing picture is intact")
    if sigterm_while_writing(
            lambda: start_render("pic.svg", "--isolines", "60", "--no-critical-points"), "render"):
        svg = open(p("pic.svg")).read()
        R.check(svg == old or svg.rstrip().endswith("</svg>"), "render SIGTERM: old or complete")

    # Determinism: byte-identical JSON (without timings) and VTP across runs and thread counts.
    run("generate", "random", "--cells", "3000", "-o", p("r.vtu"))
    run("generate", "conductor", "-o", p("c.vtu"))
    for name in ("r", "c"):
        outputs = []
        for threads in (1, 2, 7, 2):
            j, v = p(f"{name}{threads}.json"), p(f"{name}{threads}.vtp")
            run("tree", p(name + ".vtu"), "-q", "--no-timings", "--threads", threads,
                "--json", j, "--vtp", v)
            outputs.append((open(j, "rb").read(), open(v, "rb").read()))
        R.check(all(o == outputs[0] for o in outputs),
                f"{name}: JSON and VTP identical across --threads 1, 2, 7 and two runs")
        R.check(b"time_" not in outputs[0][0], f"{name}: --no-timings leaves out the timings")
        # The augmented tree too.
        a1, a7 = p(name + "a1.json"), p(name + "a7.json")
        run("tree", p(name + ".vtu"), "-q", "--no-timings", "--augmented", "--threads", 1, "--json", a1)
        run("tree", p(name + ".vtu"), "-q", "--no-timings", "--augmented", "--threads", 7, "--json", a7)
        R.check(open(a1, "rb").read() == open(a7, "rb").read(), f"{name}: augmented JSON identical")

    # Standard output that cannot be written (issue 27, item 4): every command that prints
    # reports it and exits 1, instead of losing its output with exit status 0.
    if os.path.exists("/dev/full"):
        g = p("c.vtu")
        commands = [("info", g, "--json"), ("info", g), ("tree", g), ("generate", "gauss", "-o", p("g2.vtu")),
                    ("eval", g, "--points", "-"), ("check", p("c1.json"), g)]
        for args in commands:
            with open("/dev/full", "w") as full:
                r = subprocess.run([HOCT, *args], input="0 0.2 0.2\n" * 2000, stdout=full,
                                   stderr=subprocess.PIPE, text=True)
            R.check(r.returncode == 1 and "writing the standard output failed" in r.stderr,
                    f"{' '.join(args[:1])} > /dev/full: exit {r.returncode}, stderr {r.stderr!r}")
        # Where the output can be written, the same commands exit 0.
        r = subprocess.run([HOCT, "info", g, "--json"], stdout=subprocess.DEVNULL)
        R.check(r.returncode == 0, "info --json > /dev/null exits 0")

    # Long output names (issue 27, item 6): 251 bytes, where NAME.tmp-PID-N would pass the
    # 255-byte limit; the short temporary name is used and removed.
    long_name = p("x" * 246 + ".json")
    r = run("tree", p("c.vtu"), "-q", "--json", long_name, check=False)
    R.check(r.returncode == 0 and os.path.exists(long_name), f"a 251-byte output name: {r.stderr!r}")
    R.check(leftovers(tmp) == [], f"long name: temporary files left: {leftovers(tmp)}")
    os.remove(long_name)

    # Stale temporary files (issue 27, item 5: SIGKILL cannot be caught): the next write of the
    # same output removes those of processes that no longer exist, and only those.
    dead = subprocess.Popen(["true"])
    dead.wait()
    stale = p(f".st.json.tmp-{dead.pid}-5")
    alive = p(f".st.json.tmp-{os.getpid()}-5")
    other = p(".st.json.tmp-notours")
    for f in (stale, alive, other):
        open(f, "w").write("partial")
    run("tree", p("c.vtu"), "-q", "--json", p("st.json"))
    R.check(not os.path.exists(stale), "the stale temporary file of a dead process is removed")
    R.check(os.path.exists(alive) and os.path.exists(other),
            "a live process's temporary file and a foreign name stay")
    for f in (alive, other):
        os.remove(f)

    # hoct eval's point lines (issue 27, item 8): bounded, strict, inside the reference triangle.
    with open(p("huge-line.txt"), "w") as f:
        f.write("7" * 10_000_000)
    for args, stdin, phrase in [
            (("--points", "/dev/zero"), None, "line longer than 4096 bytes"),
            (("--points", tmp), None, "is a directory"),
            (("--points", p("huge-line.txt")), None, "line longer than 4096 bytes"),
            ((), "0.5 0.2 0.2\n", "an integer cell id"),
            ((), "0 nan 0.2\n", "expected 'cell u v'"),
            ((), "0 0.2 0.2 7\n", "expected 'cell u v'"),
            ((), "0 0.8 0.4\n", "outside the reference triangle"),
            ((), "0 -0.1 0.5\n", "outside the reference triangle")]:
        if args and args[1] == "/dev/zero" and not os.path.exists("/dev/zero"):
            continue
        r = subprocess.run([HOCT, "eval", p("c.vtu"), *args], input=stdin or "", capture_output=True,
                           text=True, timeout=60)
        R.check(r.returncode == 1 and phrase in r.stderr and len(r.stderr) < 600,
                f"eval {args or repr(stdin)}: exit {r.returncode}, stderr {r.stderr[:200]!r}")
    r = subprocess.run([HOCT, "eval", p("c.vtu")], input="0 0.2 0.2\n3 1 0\n# note\n\n7 0 0\n",
                       capture_output=True, text=True)
    R.check(r.returncode == 0 and len(r.stdout.split("\n")) == 4, f"eval of good points: {r.stderr!r}")
    os.remove(p("huge-line.txt"))

    # Devices and FIFOs as input (issue 27, item 10): named, never opened (a FIFO would wait).
    os.mkfifo(p("pipe.vtu"))
    for path, phrase in [(p("pipe.vtu"), "is a FIFO"), ("/dev/null", "is a character device"),
                         ("/dev/zero", "is a character device")]:
        if not os.path.exists(path):
            continue
        try:
            r = subprocess.run([HOCT, "info", path], capture_output=True, text=True, timeout=30)
            R.check(r.returncode == 1 and phrase in r.stderr, f"info {path}: {r.returncode} {r.stderr!r}")
        except subprocess.TimeoutExpired:
            R.check(False, f"info {path} hangs")
    os.remove(p("pipe.vtu"))

    # An output that is the input, or another output (issue 27, items 2 and 7): refused before
    # anything is computed, by file identity (a symbolic link, a hard link, another spelling).
    src = p("c.vtu")
    before = open(src, "rb").read()
    os.symlink(src, p("c-link.vtu"))
    os.link(src, p("c-hard.vtu"))
    for args, phrase in [
            (("tree", src, "--json", src), "is the input"),
            (("tree", src, "--vtp", p("c-link.vtu")), "is the input"),
            (("tree", src, "--svg", p("c-hard.vtu")), "is the input"),
            (("tree", src, "--json", p("same.json"), "--vtp", os.path.join(tmp, ".", "same.json")),
             "are the same file"),
            (("convert", src, "-o", src), "is the input"),
            (("render", src, "-o", p("c-hard.vtu")), "is the input"),
            (("study", src, "--csv", p("s.out"), "--json", p("s.out")), "are the same file"),
            (("convert", src, "-o", p("conv.msh")), "name it *.vtu"),
            (("convert", src, "-o", p("conv.vtp")), "name it *.vtu"),
            (("generate", "gauss", "-o", p("g.msh")), "name it *.vtu")]:
        r = run(*args, check=False)
        R.check(r.returncode == 1 and phrase in r.stderr,
                f"{' '.join(a if not a.startswith(tmp) else os.path.basename(a) for a in args)}: "
                f"exit {r.returncode}, stderr {r.stderr!r}")
    R.check(open(src, "rb").read() == before, "the input survives every refused command")
    R.check(not any(os.path.exists(p(n)) for n in ("same.json", "s.out", "conv.msh", "conv.vtp", "g.msh")),
            "a refused command writes no output")

    # Outputs that are not regular files (issue 27, item 1). Devices are written through, never
    # replaced: our own device nodes (mknod as root; /dev/null and /dev/full are not put at risk
    # of replacement by the code under test), else the system's where this user cannot replace
    # them.
    import stat

    def device(name, minor):
        path = p(name)
        try:
            os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(1, minor))
            return path
        except (PermissionError, OSError):
            system = "/dev/" + name
            return system if os.path.exists(system) and not os.access("/dev", os.W_OK) else None

    null, full = device("null", 3), device("full", 7)
    if null:
        r = run("tree", src, "-q", "--json", null, "--vtp", null, check=False)
        R.check(r.returncode == 0 and stat.S_ISCHR(os.stat(null).st_mode),
                f"--json/--vtp to a null device: exit {r.returncode}, {r.stderr!r}, "
                f"still a device: {stat.S_ISCHR(os.stat(null).st_mode)}")
    if full:
        r = run("tree", src, "-q", "--json", full, check=False)
        R.check(r.returncode == 1 and "No space left on device" in r.stderr
                and stat.S_ISCHR(os.stat(full).st_mode),
                f"--json to a full device: exit {r.returncode}, {r.stderr!r}")
    R.check(null is not None or full is not None or os.geteuid() != 0, "no device to test with")
    # A FIFO: written through to its reader.
    os.mkfifo(p("out.fifo"))
    reader = subprocess.Popen(["cat", p("out.fifo")], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL)
    r = run("tree", src, "-q", "--json", p("out.fifo"), check=False)
    try:
        got = reader.communicate(timeout=60)[0]
    except subprocess.TimeoutExpired:  # the FIFO was replaced: its reader waits for ever
        reader.kill()
        got = reader.communicate()[0]
    R.check(r.returncode == 0 and got.startswith(b"{") and stat.S_ISFIFO(os.stat(p("out.fifo")).st_mode),
            f"--json to a FIFO: exit {r.returncode}, {r.stderr!r}, read {len(got)} bytes")
    # A symbolic link: its target gets the new content, the link stays a link.
    with open(p("target.json"), "w") as f:
        f.write(old)
    os.symlink("target.json", p("link.json"))
    run("tree", src, "-q", "--json", p("link.json"))
    R.check(os.path.islink(p("link.json")) and open(p("target.json")).read().startswith("{"),
            "--json to a symbolic link: the link stays and its target is written")
    # A dangling link: the file it names is created.
    os.symlink("made.json", p("dangling.json"))
    run("tree", src, "-q", "--json", p("dangling.json"))
    R.check(os.path.islink(p("dangling.json")) and os.path.isfile(p("made.json")),
            "--json to a dangling symbolic link creates its target")
    # An existing file's permissions (and owner) are kept; a new one gets the umask's.
    with open(p("private.json"), "w") as f:
        f.write(old)
    os.chmod(p("private.json"), 0o600)
    if os.geteuid() == 0:
        os.chown(p("private.json"), 12345, 54321)
    run("tree", src, "-q", "--json", p("private.json"))
    st = os.stat(p("private.json"))
    R.check(stat.S_IMODE(st.st_mode) == 0o600, f"mode 600 kept: {oct(stat.S_IMODE(st.st_mode))}")
    if os.geteuid() == 0:
        R.check((st.st_uid, st.st_gid) == (12345, 54321), f"owner kept: {st.st_uid}:{st.st_gid}")
    R.check(leftovers(tmp) == [], f"outputs that are not regular files: left {leftovers(tmp)}")
    # A directory as the output: refused, untouched.
    os.mkdir(p("adir"))
    r = run("tree", src, "-q", "--json", p("adir"), check=False)
    R.check(r.returncode == 1 and "is a directory" in r.stderr and os.path.isdir(p("adir")),
            f"--json to a directory: exit {r.returncode}, {r.stderr!r}")

R.finish()
