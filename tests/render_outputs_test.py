"""End-to-end checks of rendering (issues 6 and 7): `firn run --render spheres|surface --video` and `firn render`.

Usage: python3 render_outputs_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
Runs the snowball_pair scene at preview resolution, shortened and at 320x180, and checks that
every particle frame has its PNG, that video.mp4 is H.264/yuv420p with one video frame per
output frame (ffprobe), that `--render none` draws nothing, that `firn render` re-renders a
finished run from its .vtp files with other [render] settings (and refuses non-render keys), that
`--render surface` draws a frame per particle frame in both commands, and that without a working
EGL the run falls back to OSMesa.
"""
import glob
import os
import subprocess

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh
SCENE = os.path.join(ROOT, "scenes", "snowball_pair.toml")
SMALL = ["--preview", "--set", "simulation.end_time=2 ms", "--set", "render.width=320", "--set", "render.height=180"]


def run(args, env=None):
    return subprocess.run([FIRN] + args, capture_output=True, text=True, env=env)




def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    check(head[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG")
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def probe(video):
    r = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                        "stream=codec_name,pix_fmt,width,height,nb_read_frames", "-of", "default=nw=1", video],
                       capture_output=True, text=True)
    check(r.returncode == 0, f"ffprobe failed: {r.stderr}")
    return dict(line.split("=", 1) for line in r.stdout.split())


def test_video():
    out = fresh("video")
    r = run(["run", SCENE, "--out", out, "--render", "spheres", "--video"] + SMALL)
    check(r.returncode == 0, f"firn run exited {r.returncode}: {r.stderr}")
    particles = sorted(glob.glob(os.path.join(out, "particles", "*.vtp")))
    frames = sorted(glob.glob(os.path.join(out, "frames", "*.png")))
    check(len(frames) == len(particles) > 1, f"{len(frames)} PNG frames for {len(particles)} particle frames")
    check([os.path.basename(f)[:5] for f in frames] == [os.path.basename(p)[:5] for p in particles],
          "PNG and .vtp frame numbers differ")
    check(all(png_size(f) == (320, 180) for f in frames), "a frame is not 320x180")
    check(not glob.glob(os.path.join(out, "**", "*.tmp"), recursive=True), "temporary files left behind")
    s = probe(os.path.join(out, "video.mp4"))
    check(s.get("codec_name") == "h264" and s.get("pix_fmt") == "yuv420p", f"video stream {s}")
    check(int(s.get("nb_read_frames", -1)) == len(frames), f"{s.get('nb_read_frames')} video frames for {len(frames)}")


def test_none():
    out = fresh("none")
    r = run(["run", SCENE, "--out", out, "--render", "none"] + SMALL)
    check(r.returncode == 0, f"firn run exited {r.returncode}: {r.stderr}")
    check(not os.path.exists(os.path.join(out, "frames")), "--render none made frames")
    r = run(["run", SCENE, "--out", fresh("none_video"), "--video"] + SMALL)
    check(r.returncode == 2 and "--render" in r.stderr, f"--video without --render: {r.returncode} {r.stderr}")


def test_rerender():
    out = fresh("rerender")
    r = run(["run", SCENE, "--out", out, "--render", "spheres"] + SMALL)
    check(r.returncode == 0, f"firn run exited {r.returncode}: {r.stderr}")
    first = os.path.join(out, "frames", "00001.png")
    with open(first, "rb") as f:
        by_material = f.read()
    r = run(["render", out, "--gl", "osmesa", "--set", "render.color_by=stress", "--set", "render.width=160",
             "--set", "render.height=90"])
    check(r.returncode == 0, f"firn render exited {r.returncode}: {r.stderr}")
    check(png_size(first) == (160, 90), "firn render did not apply render.width/height")
    with open(first, "rb") as f:
        check(f.read() != by_material, "the re-rendered frame is unchanged")
    frames = glob.glob(os.path.join(out, "frames", "*.png"))
    check(len(frames) == len(glob.glob(os.path.join(out, "particles", "*.vtp"))), "firn render skipped frames")
    small = ["--set", "render.width=160", "--set", "render.height=90", "--set", "render.cutaway=true"]
    frames = []
    for colour in [[], ["--set", "materials.core.color=[0.2, 0.8, 0.2]"]]:
        r = run(["render", out] + small + colour)
        check(r.returncode == 0, f"firn render {colour} exited {r.returncode}: {r.stderr}")
        with open(first, "rb") as f:
            frames.append(f.read())
    check(frames[0] != frames[1], "a material's colour set by firn render did not change the frame")
    r = run(["render", out, "--set", "simulation.dx=0.001"])
    check(r.returncode == 2 and "render." in r.stderr, f"a non-render --set: {r.returncode} {r.stderr}")


def test_surface():
    # --render surface draws the reconstructed snow surface; firn render redraws it from the .vtp
    # files (anchored to the first frame); both differ from the spheres of the same frame.
    out = fresh("surface")
    short = SMALL + ["--set", "simulation.end_time=1 ms"]
    r = run(["run", SCENE, "--out", out, "--render", "surface"] + short)
    check(r.returncode == 0, f"firn run --render surface exited {r.returncode}: {r.stderr}")
    particles = sorted(glob.glob(os.path.join(out, "particles", "*.vtp")))
    frames = sorted(glob.glob(os.path.join(out, "frames", "*.png")))
    check(len(frames) == len(particles) > 1, f"{len(frames)} surface frames for {len(particles)} particle frames")
    check(all(png_size(f) == (320, 180) for f in frames), "a surface frame is not 320x180")
    last = frames[-1]
    images = {}
    for style in ["surface", "spheres"]:
        r = run(["render", out, "--render", style])
        check(r.returncode == 0, f"firn render --render {style} exited {r.returncode}: {r.stderr}")
        check(len(glob.glob(os.path.join(out, "frames", "*.png"))) == len(particles), f"firn render {style} skipped frames")
        with open(last, "rb") as f:
            images[style] = f.read()
    check(images["surface"] != images["spheres"], "the surface frame looks like the spheres frame")


def test_fallback():
    # glvnd with no EGL vendor: EGL fails, and without --gl the run falls back to OSMesa.
    env = dict(os.environ, __EGL_VENDOR_LIBRARY_FILENAMES="/nonexistent/egl_vendor.json")
    out = fresh("fallback")
    r = run(["run", SCENE, "--out", out, "--render", "spheres"] + SMALL, env)
    check(r.returncode == 0 and "osmesa" in r.stdout, f"no fallback to OSMesa: {r.returncode} {r.stdout} {r.stderr}")
    check(len(glob.glob(os.path.join(out, "frames", "*.png"))) > 1, "no frames from OSMesa")
    r = run(["run", SCENE, "--out", fresh("fallback_egl"), "--render", "spheres", "--gl", "egl"] + SMALL, env)
    check(r.returncode == 2 and "EGL" in r.stderr and r.stderr.count("\n") == 1, f"--gl egl without EGL: {r.stderr}")


os.makedirs(SCRATCH, exist_ok=True)
globals()["test_" + TEST]()
print("ok")
