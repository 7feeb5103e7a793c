"""The *SECTION_SOLID_SPG cards the verification decks share (keywords.md §2.6): ELFORM 47,
cubic spline with box support, DX = DY = DZ = 1.5, updated-Lagrangian kernel renewed every 15
steps, no bond failure, ITB 3 (MC-SPG), MSFAC 1, PDAMP -0.001."""


def spg_section(secid=1):
    return [
        "*SECTION_SOLID_SPG",
        "$    SECID    ELFORM",
        f"{secid:10d}        47",
        "$       DX        DY        DZ   ISPLINE    KERNEL    LSCALE    SMSTEP       MSC",
        "       1.5       1.5       1.5         0         0                  15       0.0",
        "$     IDAM        FS   STRETCH       ITB     MSFAC       ISC     BOXID     PDAMP",
        "         1   1.0E+11   1.0E+10         3       1.0         0         0    -0.001",
    ]
