#!/usr/bin/python3
"""Renders one state of a run (d3plot.pvd) to a PNG offscreen with VTK, as a user would see it in
ParaView: hexahedra and shells as surfaces, SPG particles as small spheres, coloured by effective
plastic strain; optionally cut by the plane y = 0 (keeping y < 0) to look into a hole or a bar's
core, and with parts left out (e.g. the screw, to see the threads it formed). Needs an X display:
on a machine without one run it under `xvfb-run -a` (tools/setup.sh installs xvfb).

usage: render_state.py RUN_DIR OUT.png [--state N (default: last)] [--cut] [--hide-part ID ...]
                       [--ghost-part ID ...] [--box XMIN XMAX YMIN YMAX ZMIN ZMAX]
                       [--azimuth 30] [--elevation 20] [--zoom 1.0] [--size 1200 900]
                       [--title TEXT] [--range LO HI]
"""
import argparse

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtkIdTypeArray, vtk_to_numpy

from d3plot import read_state, run_title, states


def cells_where(grid, array, lo, hi, invert=False):
    """The cells of `grid` whose cell value `array` is within [lo, hi] (outside with invert)."""
    t = vtk.vtkThreshold()
    t.SetInputData(grid)
    t.SetInputArrayToProcess(0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_CELLS, array)
    t.SetLowerThreshold(lo)
    t.SetUpperThreshold(hi)
    t.SetThresholdFunction(vtk.vtkThreshold.THRESHOLD_BETWEEN)
    t.SetInvert(invert)
    t.Update()
    return t.GetOutput()


def part_cells(grid, part, keep):
    """The cells of part `part` (keep=True) or of every other part (keep=False)."""
    return cells_where(grid, "part_id", part - 0.5, part + 0.5, invert=not keep)


def alive_cells(grid):
    """Drops eroded elements (erosion_state != 0), as LS-PrePost hides them."""
    if grid.GetCellData().GetArray("erosion_state") is None:
        return grid
    return cells_where(grid, "erosion_state", -0.5, 0.5)


def cells_inside(grid, function, boundary_cells):
    """The cells inside an implicit function (all their points, or any with boundary_cells)."""
    extract = vtk.vtkExtractGeometry()
    extract.SetInputData(grid)
    extract.SetImplicitFunction(function)
    extract.ExtractInsideOn()
    extract.SetExtractBoundaryCells(boundary_cells)
    extract.Update()
    return extract.GetOutput()


def inside_box(grid, bounds):
    """The cells with all points inside the box (xmin xmax ymin ymax zmin zmax): keeps the view
    on the region of interest when debris has flown far off."""
    box = vtk.vtkBox()
    box.SetBounds(*bounds)
    return cells_inside(grid, box, boundary_cells=False)


def cut_half(grid):
    """Keeps the cells with any point at y <= 0 (whole cells: particles stay round)."""
    plane = vtk.vtkPlane()
    plane.SetOrigin(0.0, 0.0, 0.0)
    plane.SetNormal(0.0, 1.0, 0.0)
    return cells_inside(grid, plane, boundary_cells=True)


def split_particles(grid):
    """(the particles: vertex cells, the other cells), each an unstructured grid or None."""
    is_vertex = vtk_to_numpy(grid.GetCellTypesArray()) == vtk.VTK_VERTEX

    def extract(mask):
        if not mask.any():
            return None
        node = vtk.vtkSelectionNode()
        node.SetFieldType(vtk.vtkSelectionNode.CELL)
        node.SetContentType(vtk.vtkSelectionNode.INDICES)
        node.SetSelectionList(numpy_to_vtkIdTypeArray(np.flatnonzero(mask).astype(np.int64),
                                                      deep=True))
        selection = vtk.vtkSelection()
        selection.AddNode(node)
        e = vtk.vtkExtractSelection()
        e.SetInputData(0, grid)
        e.SetInputData(1, selection)
        e.Update()
        return e.GetOutput()

    return extract(is_vertex), extract(~is_vertex)


def strain_lut(lo, hi):
    lut = vtk.vtkLookupTable()
    lut.SetRange(lo, hi)
    lut.SetHueRange(0.667, 0.0)  # blue (0) to red (large strain), as LS-PrePost's fringe
    lut.Build()
    return lut


def strain_actor(data, lut, cell_data):
    """An actor drawing `data` coloured by its effective_plastic_strain (cell or point array)."""
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputData(data)
    if cell_data:
        mapper.SetScalarModeToUseCellFieldData()
    else:
        mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("effective_plastic_strain")
    mapper.SetLookupTable(lut)
    mapper.UseLookupTableScalarRangeOn()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    return actor


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("png")
    ap.add_argument("--state", type=int, default=-1)
    ap.add_argument("--cut", action="store_true", help="keep y <= 0 only")
    ap.add_argument("--hide-part", type=int, nargs="*", default=[])
    ap.add_argument("--ghost-part", type=int, nargs="*", default=[],
                    help="parts drawn grey and translucent (e.g. a tool)")
    ap.add_argument("--box", type=float, nargs=6, default=None,
                    metavar=("XMIN", "XMAX", "YMIN", "YMAX", "ZMIN", "ZMAX"),
                    help="show only the cells inside this box")
    ap.add_argument("--azimuth", type=float, default=30.0)
    ap.add_argument("--elevation", type=float, default=20.0)
    ap.add_argument("--zoom", type=float, default=1.0)
    ap.add_argument("--size", type=int, nargs=2, default=[1200, 900])
    ap.add_argument("--title", default="")
    ap.add_argument("--range", type=float, nargs=2, default=None,
                    help="colour range of the plastic strain (default: 0 to its largest value)")
    a = ap.parse_args()

    t, name = states(a.run)[a.state]
    grid = alive_cells(read_state(a.run, name))
    for p in a.hide_part:
        grid = part_cells(grid, p, keep=False)
    ghosts = [part_cells(grid, p, keep=True) for p in a.ghost_part]
    for p in a.ghost_part:
        grid = part_cells(grid, p, keep=False)
    if a.box:
        grid = inside_box(grid, a.box)
        ghosts = [inside_box(g, a.box) for g in ghosts]
    if a.cut:
        grid = cut_half(grid)
        ghosts = [cut_half(g) for g in ghosts]

    strain = grid.GetCellData().GetArray("effective_plastic_strain")
    lo, hi = a.range if a.range else (0.0, max(strain.GetRange()[1], 1e-6))
    lut = strain_lut(lo, hi)
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)

    particles, others = split_particles(grid)
    if others is not None:  # hexahedra and shells: their outer faces, with the mesh lines
        surface = vtk.vtkDataSetSurfaceFilter()
        surface.SetInputData(others)
        surface.Update()
        actor = strain_actor(surface.GetOutput(), lut, cell_data=True)
        actor.GetProperty().EdgeVisibilityOn()
        actor.GetProperty().SetEdgeColor(0.25, 0.25, 0.25)
        actor.GetProperty().SetLineWidth(0.5)
        renderer.AddActor(actor)
    if particles is not None:  # particles: spheres at the points, the cell value on the point
        to_points = vtk.vtkCellDataToPointData()
        to_points.SetInputData(particles)
        to_points.Update()
        actor = strain_actor(to_points.GetOutput(), lut, cell_data=False)
        actor.GetProperty().SetRepresentationToPoints()
        actor.GetProperty().RenderPointsAsSpheresOn()
        actor.GetProperty().SetPointSize(max(3.0, a.size[0] / 220.0))
        renderer.AddActor(actor)
    for g in ghosts:
        surface = vtk.vtkDataSetSurfaceFilter()
        surface.SetInputData(g)
        mapper = vtk.vtkDataSetMapper()
        mapper.SetInputConnection(surface.GetOutputPort())
        mapper.ScalarVisibilityOff()
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(0.6, 0.6, 0.6)
        actor.GetProperty().SetOpacity(0.35)
        renderer.AddActor(actor)

    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("effective plastic strain")
    bar.SetNumberOfLabels(5)
    bar.SetWidth(0.08)
    bar.SetHeight(0.5)
    bar.SetPosition(0.84, 0.2)
    bar.UnconstrainedFontSizeOn()
    font = max(14, a.size[0] // 60)
    for prop, size in ((bar.GetTitleTextProperty(), font), (bar.GetLabelTextProperty(), font - 2)):
        prop.SetColor(0.0, 0.0, 0.0)
        prop.SetFontSize(size)
        prop.ItalicOff()
        prop.BoldOff()
        prop.ShadowOff()
    renderer.AddViewProp(bar)
    text = vtk.vtkTextActor()
    text.SetInput(a.title or f"{run_title(a.run)}: t = {t * 1e3:.4g} ms")
    text.GetTextProperty().SetColor(0.0, 0.0, 0.0)
    text.GetTextProperty().SetFontSize(font)
    text.SetPosition(10, a.size[1] - 10 - font)
    renderer.AddViewProp(text)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 1.0, 0.0)  # look along -y at the cut face (y = 0) of the kept half
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCamera()
    camera.Azimuth(a.azimuth)
    camera.Elevation(a.elevation)
    camera.Zoom(a.zoom)
    renderer.ResetCameraClippingRange()

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*a.size)
    window.Render()
    image = vtk.vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(a.png)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    print(f"wrote {a.png} (state at t = {t:.6e} s, plastic strain colour range {lo:g} … {hi:g})")


if __name__ == "__main__":
    main()
