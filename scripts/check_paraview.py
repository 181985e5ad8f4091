"""ParaView's own Python opens a run's fields (docs/output.md, "Checking with ParaView").

  pvpython --force-offscreen-rendering scripts/check_paraview.py DIR OUT.png

Loads DIR/fields.xdmf (and DIR/joints.xdmf when there), checks at every time step that ParaView
reads as many points and cells as fields.h5 holds and every array the xdmf names, renders the
deformed shells coloured by the displacement magnitude with the joint lines, and writes the picture of the step of
largest displacement to OUT.png; the picture must be non-trivial (many colours, most of it not background).
Exit status 1 with a message on any failure.
"""
import os
import sys

import h5py
import numpy as np
from paraview import simple as pv

d, png = sys.argv[1], sys.argv[2]
h5 = h5py.File(f"{d}/fields.h5", "r")
npoints, ncells = h5["/shells/coordinates"].shape[0], h5["/shells/cells"].shape[0]
fails = []

shells = pv.OpenDataFile(f"{d}/fields.xdmf")
shells.UpdatePipelineInformation()
times = list(shells.TimestepValues) if shells.TimestepValues else []
if len(times) != len(h5["steps"]):
    fails.append(f"ParaView sees {len(times)} time steps, fields.h5 has {len(h5['steps'])}")
view = pv.CreateRenderView()
view.ViewSize = [900, 600]
view.OrientationAxesVisibility = 0
merged = pv.MergeBlocks(Input=shells)
warp = pv.WarpByVector(Input=merged, Vectors=["POINTS", "displacement"], ScaleFactor=10.0)
shown = pv.Show(warp, view)
pv.ColorBy(shown, ("POINTS", "displacement", "Magnitude"))
joints = None
try:
    joints = pv.OpenDataFile(f"{d}/joints.xdmf")
    jshown = pv.Show(pv.MergeBlocks(Input=joints), view)
    jshown.LineWidth = 3
except Exception as e:  # noqa: BLE001
    fails.append(f"joints.xdmf: {e}")
for t in times:
    merged.UpdatePipeline(t)
    info = merged.GetDataInformation()
    if info.GetNumberOfPoints() != npoints or info.GetNumberOfCells() != ncells:
        fails.append(f"time {t}: ParaView reads {info.GetNumberOfPoints()} points, {info.GetNumberOfCells()} cells; fields.h5 {npoints}, {ncells}")
    names = {merged.PointData[i].Name for i in range(len(merged.PointData))} | {merged.CellData[i].Name for i in range(len(merged.CellData))}
    for need in ("displacement", "rotation", "part", "node"):
        if need not in names:
            fails.append(f"time {t}: no array {need} (ParaView has {sorted(names)})")
    view.ViewTime = t
    pv.Render(view)
# The picture: the step of largest displacement, seen obliquely.
tmax = max(times, key=lambda t: np.abs(h5[f"/steps/{int(t):06d}/shells/displacement"][:]).max())
# Scale the displacements so that the largest is a tenth of the model's size: a fixed factor turns
# a flexible model into a tangle and leaves a stiff one undeformed.
xyz = np.asarray(h5["/shells/coordinates"][:], dtype=float)
largest = np.abs(h5[f"/steps/{int(tmax):06d}/shells/displacement"][:]).max()
if largest > 0:
    warp.ScaleFactor = 0.1 * np.ptp(xyz, axis=0).max() / largest
view.ViewTime = tmax
pv.Render(view)
shown.RescaleTransferFunctionToDataRange(False, True)
# Look along the shells' dominant normal (the eigenvector of sum n n^T over the stored normals),
# then tilt: a view along a fixed axis sees a plate lying in another plane edge-on, as a line.
normals = np.asarray(h5["/shells/normal"][:], dtype=float).reshape(-1, 3)
w, v = np.linalg.eigh(normals.T @ normals)
look = v[:, int(np.argmax(w))]
b = merged.GetDataInformation().GetBounds()
centre = np.array([0.5 * (b[2 * i] + b[2 * i + 1]) for i in range(3)])
size = max(b[1] - b[0], b[3] - b[2], b[5] - b[4], 1e-12)
up = np.cross(look, np.eye(3)[int(np.argmin(np.abs(look)))])
view.CameraPosition = list(centre + 2 * size * look)
view.CameraFocalPoint = list(centre)
view.CameraViewUp = list(up / np.linalg.norm(up))
view.ResetCamera()
camera = view.GetActiveCamera()
camera.Elevation(-35)
camera.Azimuth(15)
view.ResetCamera()
pv.SaveScreenshot(png, view, ImageResolution=[900, 600])

import matplotlib.image as mpimg  # noqa: E402

img = mpimg.imread(png)[:, :, :3]
colours = len(np.unique((img * 255).astype(np.uint8).reshape(-1, 3), axis=0))
background = np.mean(np.all(np.abs(img - img[0, 0]) < 1e-3, axis=2))
if colours < 20 or background > 0.97:
    fails.append(f"{png}: {colours} colours, {background:.0%} background: an empty picture")
for f in fails:
    print("FAIL:", f)
print(f"check_paraview: {len(times)} time steps, {npoints} points, {ncells} cells; {png}: {colours} colours, {background:.0%} background")
print("check_paraview: PASS" if not fails else f"check_paraview: {len(fails)} failure(s)", flush=True)
# ParaView's teardown of the GLX context under Xvfb can fail after the work is done: skip it.
os._exit(1 if fails else 0)
