"""Reading mcdyna's d3plot-like VTK series (d3plot.pvd + d3plot_NNNN.vtu), shared by the
verification scripts in this directory."""
import re

import vtk


def states(results):
    """(time, file name) of every state listed in RESULTS/d3plot.pvd, in order."""
    with open(f"{results}/d3plot.pvd") as f:
        return [(float(t), name)
                for t, name in re.findall(r'timestep="([^"]+)".*?file="([^"]+)"', f.read())]


def read_state(results, name):
    """The unstructured grid of one state file."""
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(f"{results}/{name}")
    reader.Update()
    return reader.GetOutput()
