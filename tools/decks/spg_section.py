"""The *SECTION_SOLID_SPG cards the verification decks share (keywords.md §2.6): ELFORM 47,
cubic spline with box support, DX = DY = DZ = 1.5, updated-Lagrangian kernel checked every 15
steps, ITB 3 (MC-SPG), MSFAC 1, PDAMP -0.001; no bond failure unless FS and STRETCH are given
(IDAM 1: a bond breaks when its mean effective plastic strain exceeds FS and it is stretched
beyond STRETCH); MSC 0 (the paper's MC-SPG) unless msc=1 asks for the control of low-energy
modes (src/solver/spg/mode_control.cpp)."""


def field(v):
    """A real in a 10-column field: large values in E notation (1.0E+11), others plainly."""
    return f"{v:10.1E}" if abs(v) >= 1.0e5 else f"{v:10g}"


def spg_section(secid=1, fs=1.0e11, stretch=1.0e10, msc=0):
    return [
        "*SECTION_SOLID_SPG",
        "$    SECID    ELFORM",
        f"{secid:10d}        47",
        "$       DX        DY        DZ   ISPLINE    KERNEL    LSCALE    SMSTEP       MSC",
        f"       1.5       1.5       1.5         0         0                  15{float(msc):10.1f}",
        "$     IDAM        FS   STRETCH       ITB     MSFAC       ISC     BOXID     PDAMP",
        f"         1{field(fs)}{field(stretch)}         3       1.0         0         0    -0.001",
    ]
