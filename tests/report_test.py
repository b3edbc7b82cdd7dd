"""End-to-end checks of `firn report` and contact sheets (issue 18, items 5 and 6).

Usage: python3 report_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
run:     `firn run --render spheres --video --report` on a short two_spheres run writes report.html
         whose every image is a file beside it, with no network reference, the scene's parameters,
         the plots, six frames and the video; `firn report` rewrites it and refuses a folder that is
         no run's or sweep's.
sweep:   a two-run sweep with --render spheres --report writes contact sheets (every run's middle
         and last frame in a grid), each run's own report and the sweep's page, whose links and
         images all resolve, with the pivot table of the plotted metric; `firn sweep --collect
         --report` writes the same sheets and page again.
browser: both pages opened in Debian's headless chromium load with no console error and every
         image shown (the page's own check, read from the DOM), and their screenshots are not
         blank. Exit status 77 (skipped) where chromium is not installed.
"""
import os
import re
import shutil
import struct
import subprocess
import sys
import zlib

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh
SCENE = os.path.join(ROOT, "scenes", "two_spheres.toml")
SMALL = ["--preview", "--set", "simulation.end_time=0.8", "--set", "render.width=320", "--set", "render.height=180"]


def firn(*args):
    return subprocess.run([FIRN] + list(args), capture_output=True, text=True, timeout=300)


def make_run(out):
    r = firn("run", SCENE, "--out", out, "--render", "spheres", "--video", "--report", *SMALL)
    check(r.returncode == 0, f"firn run --report exited {r.returncode}: {r.stderr}")
    check(f"report in {out}/report.html" in r.stdout, f"firn run did not say where the report is: {r.stdout}")
    return os.path.join(out, "report.html")


def make_sweep(out):
    r = firn("sweep", SCENE, "--out", out, "--vary", "simulation.transfer=pic,apic", "--plot", "energy_residual",
             "--render", "spheres", "--report", "--jobs", "2", *SMALL)
    check(r.returncode == 0, f"firn sweep --render spheres --report exited {r.returncode}: {r.stderr}")
    return os.path.join(out, "report.html")


def page(path):
    check(os.path.isfile(path), f"{path} missing")
    with open(path, encoding="utf-8") as f:
        return f.read()


def check_self_contained(path):
    """Every src and href is a relative path to a file or folder beside the page; nothing is fetched."""
    html = page(path)
    check(not re.search(r"https?://|src=\"//|<link\b", html), f"{path} refers to the network")
    srcs = re.findall(r"<img src=\"([^\"]+)\"", html)
    for ref in srcs + re.findall(r"(?:src|href)=\"([^\"]+)\"", html):
        check(not os.path.isabs(ref) and ".." not in ref.split("/"), f"{path}: {ref} is not beside the page")
        check(os.path.exists(os.path.join(os.path.dirname(path), ref)), f"{path}: {ref} does not exist")
    return html, srcs


def test_run():
    out = fresh("run")
    html, srcs = check_self_contained(make_run(out))
    for part in ["<h2>Status and timings</h2>", "<td>status</td><td>ok</td>", "<caption>[simulation]</caption>",
                 "<caption>[materials.elastic]</caption>", "<caption>[[bodies]]</caption>",
                 "<video controls preload=\"metadata\" src=\"video.mp4\">", 'href="scene.resolved.toml"']:
        check(part in html, f"report.html lacks {part}")
    frames = [s for s in srcs if s.startswith("frames/")]
    check(len(frames) == 6 and frames[0] == "frames/00000.png", f"frame strip {frames}")
    plots = [s for s in srcs if s.startswith("plots/")]
    check("plots/kinetic_energy.png" in plots and "plots/energy_residual.png" in plots, f"plots {plots}")
    os.remove(os.path.join(out, "report.html"))
    r = firn("report", out)
    check(r.returncode == 0 and os.path.isfile(os.path.join(out, "report.html")), f"firn report: {r.stderr}")
    r = firn("report", os.path.join(out, "frames"))
    check(r.returncode == 2 and "not a run's output folder" in r.stderr, f"firn report on frames/: {r.returncode} {r.stderr}")


def png_pixels(path):
    """(width, height, rows of pixel tuples) of an 8-bit RGB or RGBA PNG, unfiltered."""
    with open(path, "rb") as f:
        data = f.read()
    check(data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour = header[:4]
    check(depth == 8 and colour in (2, 6), f"{path}: bit depth {depth}, colour type {colour}")
    bpp = 3 if colour == 2 else 4
    raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[i:i + 3]) for i in range(0, stride, bpp)])
        prev = line
    return width, height, rows


def test_sweep():
    out = fresh("sweep")
    html, srcs = check_self_contained(make_sweep(out))
    sheets = sorted(os.listdir(os.path.join(out, "contact_sheets")))
    frames = sorted(os.listdir(os.path.join(out, "runs", "001_pic", "frames")))
    check(len(frames) > 2 and sheets == sorted({frames[len(frames) // 2], frames[-1]}),
          f"contact sheets {sheets} for frames {frames}")
    for sheet in sheets:
        check(f"contact_sheets/{sheet}" in srcs, f"report.html does not show contact_sheets/{sheet}")
        width, height, rows = png_pixels(os.path.join(out, "contact_sheets", sheet))
        # Two 320 x 180 frames side by side under one label line each at twice the font's size.
        check((width, height) == (6 + 2 * (320 + 6), 6 + 20 + 6 + 180 + 6), f"{sheet} is {width} x {height}")
        check(rows[6 + 26 + 90][6 + 160] != (255, 255, 255) and rows[6 + 26 + 90][6 + 326 + 160] != (255, 255, 255),
              f"{sheet}: a tile holds no frame")
        check(any(p[0] < 100 for p in rows[6 + 10][6:6 + 320]), f"{sheet}: no label over the first tile")
    for run in ["001_pic", "002_apic"]:
        check(f'href="runs/{run}/report.html"' in html, f"report.html does not link runs/{run}/report.html")
        check_self_contained(os.path.join(out, "runs", run, "report.html"))
    # --render is kept in sweep.args: --collect writes the sheets again, and --report the page.
    shutil.rmtree(os.path.join(out, "contact_sheets"))
    os.remove(os.path.join(out, "report.html"))
    r = firn("sweep", "--collect", out, "--report")
    check(r.returncode == 0, f"firn sweep --collect --report exited {r.returncode}: {r.stderr}")
    check(sorted(os.listdir(os.path.join(out, "contact_sheets"))) == sheets, "--collect did not write the contact sheets")
    check(page(os.path.join(out, "report.html")) == html, "--collect --report wrote another page")
    for part in ["plots/energy_residual.png", "<caption>energy_residual by simulation.transfer (columns); ratio: apic / pic</caption>",
                 "<th colspan=\"3\">mean_energy_residual</th>", "<caption>sweep.csv: one row per finished run</caption>"]:
        check(part in html, f"report.html lacks {part}")


def chromium():
    for name in ["chromium", "chromium-browser"]:
        if shutil.which(name):
            return shutil.which(name)
    return None


def browse(browser, path, shot):
    """The page's DOM after it has loaded, and chromium's console lines; a screenshot to `shot`."""
    common = [browser, "--headless", "--disable-gpu", "--no-sandbox", "--no-first-run", "--hide-scrollbars",
              "--enable-logging=stderr", "--v=0", "--virtual-time-budget=5000", "--window-size=1200,2000",
              f"--user-data-dir={os.path.dirname(shot)}/profile"]
    url = "file://" + os.path.abspath(path)
    dom = subprocess.run(common + ["--dump-dom", url], capture_output=True, text=True, timeout=120)
    check(dom.returncode == 0, f"chromium --dump-dom exited {dom.returncode}: {dom.stderr[-2000:]}")
    r = subprocess.run(common + [f"--screenshot={shot}", url], capture_output=True, text=True, timeout=120)
    check(r.returncode == 0 and os.path.isfile(shot), f"chromium --screenshot exited {r.returncode}: {r.stderr[-2000:]}")
    console = [line for line in (dom.stderr + r.stderr).splitlines() if "CONSOLE" in line]
    return dom.stdout, console


def test_browser():
    browser = chromium()
    if not browser:
        print("SKIP: chromium is not installed (make test installs it)")
        sys.exit(77)
    out = fresh("browser")
    for name, path in [("run", make_run(os.path.join(out, "run"))), ("sweep", make_sweep(os.path.join(out, "sweep")))]:
        shot = os.path.join(out, name + ".png")
        dom, console = browse(browser, path, shot)
        check(not console, f"{name} report: console messages {console}")
        state = re.search(r'<html[^>]*data-report-check="([^"]*)"', dom)
        check(state is not None, f"{name} report: the page's check did not run: {dom[:500]}")
        check(state.group(1) == "ok", f"{name} report: {state.group(1)}")
        check(dom.count("<img ") == page(path).count("<img "), f"{name} report: images missing from the DOM")
        width, height, rows = png_pixels(shot)
        colours = {p for row in rows[::4] for p in row[::4]}
        check((width, height) == (1200, 2000), f"{name} screenshot is {width} x {height}")
        check(len(colours) > 64, f"{name} screenshot is blank or nearly: {len(colours)} colours")


{"run": test_run, "sweep": test_sweep, "browser": test_browser}[TEST]()
