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


def run_title(results):
    """What a picture of a run is called by default: the deck's *TITLE as d3hsp echoes it (the
    last run in it), else the deck's file name; never the machine's run folder."""
    title = deck = ""
    try:
        with open(f"{results}/d3hsp") as f:
            for line in f:
                if line.startswith("deck:"):
                    deck = line.split(":", 1)[1].strip().rsplit("/", 1)[-1]
                m = re.match(r"\s+title\s+(.*\S)", line)
                if m:
                    title = m.group(1)
    except OSError:
        pass
    return title or deck or "mcdyna run"
