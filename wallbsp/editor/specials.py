"""DOOM's line and sector specials by number, with the names map editors show.

The trigger prefix is DOOM's: W walk over, S switch (use), G gun (shoot), D door (use,
manual), 1 once, R repeatable.  Facts of DOOM's p_spec.c, p_switch.c and p_doors.c (the
numbers and what each does); the wording is ours.
"""
from __future__ import annotations

__all__ = ["LINE_SPECIALS", "SECTOR_SPECIALS", "line_special_name", "sector_special_name"]

_LINES = """
1 DR Door open wait close
2 W1 Door open stay
3 W1 Door close
4 W1 Door open wait close
5 W1 Floor raise to lowest ceiling
6 W1 Crusher start fast
7 S1 Stairs raise by 8
8 W1 Stairs raise by 8
9 S1 Donut
10 W1 Lift lower wait raise
11 S1 Exit level
12 W1 Light to brightest neighbour
13 W1 Light to 255
14 S1 Floor raise by 32, change texture
15 S1 Floor raise by 24, change texture
16 W1 Door close wait open
17 W1 Light starts blinking
18 S1 Floor raise to next higher
19 W1 Floor lower to highest neighbour
20 S1 Floor raise to next higher, change texture
21 S1 Lift lower wait raise
22 W1 Floor raise to next higher, change texture
23 S1 Floor lower to lowest
24 G1 Floor raise to lowest ceiling
25 W1 Crusher start slow
26 DR Door open wait close, blue key
27 DR Door open wait close, yellow key
28 DR Door open wait close, red key
29 S1 Door open wait close
30 W1 Floor raise by shortest lower texture
31 D1 Door open stay
32 D1 Door open stay, blue key
33 D1 Door open stay, red key
34 D1 Door open stay, yellow key
35 W1 Light to 35
36 W1 Floor lower to 8 above highest neighbour, fast
37 W1 Floor lower to lowest, change texture
38 W1 Floor lower to lowest
39 W1 Teleport
40 W1 Ceiling raise to highest
41 S1 Ceiling lower to floor
42 SR Door close
43 SR Ceiling lower to floor
44 W1 Ceiling lower to 8 above floor
45 SR Floor lower to highest neighbour
46 GR Door open stay
47 G1 Floor raise to next higher, change texture
48 Scroll the wall's texture left
49 S1 Crusher start slow
50 S1 Door close
51 S1 Secret exit
52 W1 Exit level
53 W1 Floor start moving up and down
54 W1 Floor stop moving
55 S1 Floor raise to 8 below ceiling, crush
56 W1 Floor raise to 8 below ceiling, crush
57 W1 Crusher stop
58 W1 Floor raise by 24
59 W1 Floor raise by 24, change texture
60 SR Floor lower to lowest
61 SR Door open stay
62 SR Lift lower wait raise
63 SR Door open wait close
64 SR Floor raise to lowest ceiling
65 SR Floor raise to 8 below ceiling, crush
66 SR Floor raise by 24, change texture
67 SR Floor raise by 32, change texture
68 SR Floor raise to next higher, change texture
69 SR Floor raise to next higher
70 SR Floor lower to 8 above highest neighbour, fast
71 S1 Floor lower to 8 above highest neighbour, fast
72 WR Ceiling lower to 8 above floor
73 WR Crusher start slow
74 WR Crusher stop
75 WR Door close
76 WR Door close wait open
77 WR Crusher start fast
79 WR Light to 35
80 WR Light to brightest neighbour
81 WR Light to 255
82 WR Floor lower to lowest
83 WR Floor lower to highest neighbour
84 WR Floor lower to lowest, change texture
86 WR Door open stay
87 WR Floor start moving up and down
88 WR Lift lower wait raise
89 WR Floor stop moving
90 WR Door open wait close
91 WR Floor raise to lowest ceiling
92 WR Floor raise by 24
93 WR Floor raise by 24, change texture
94 WR Floor raise to 8 below ceiling, crush
95 WR Floor raise to next higher, change texture
96 WR Floor raise by shortest lower texture
97 WR Teleport
98 WR Floor lower to 8 above highest neighbour, fast
99 SR Door open stay fast, blue key
100 W1 Stairs raise by 16, fast
101 S1 Floor raise to lowest ceiling
102 S1 Floor lower to highest neighbour
103 S1 Door open stay
104 W1 Light to darkest neighbour
105 WR Door open wait close, fast
106 WR Door open stay, fast
107 WR Door close, fast
108 W1 Door open wait close, fast
109 W1 Door open stay, fast
110 W1 Door close, fast
111 S1 Door open wait close, fast
112 S1 Door open stay, fast
113 S1 Door close, fast
114 SR Door open wait close, fast
115 SR Door open stay, fast
116 SR Door close, fast
117 DR Door open wait close, fast
118 D1 Door open stay, fast
119 W1 Floor raise to next higher
120 WR Lift lower wait raise, fast
121 W1 Lift lower wait raise, fast
122 S1 Lift lower wait raise, fast
123 SR Lift lower wait raise, fast
124 W1 Secret exit
125 W1 Teleport, monsters only
126 WR Teleport, monsters only
127 S1 Stairs raise by 16, fast
128 WR Floor raise to next higher
129 WR Floor raise to next higher, fast
130 W1 Floor raise to next higher, fast
131 S1 Floor raise to next higher, fast
132 SR Floor raise to next higher, fast
133 S1 Door open stay fast, blue key
134 SR Door open stay fast, red key
135 S1 Door open stay fast, red key
136 SR Door open stay fast, yellow key
137 S1 Door open stay fast, yellow key
138 SR Light to 255
139 SR Light to 35
140 S1 Floor raise by 512
141 W1 Crusher start, silent
"""

_SECTORS = """
1 Light blinks randomly
2 Light blinks every 0.5 s
3 Light blinks every 1 s
4 Light blinks 0.5 s, 20% damage
5 10% damage
7 5% damage
8 Light glows
9 Secret
10 Door closes after 30 s
11 20% damage, exit when nearly dead
12 Light blinks 0.5 s, in step
13 Light blinks 1 s, in step
14 Door opens after 5 minutes
16 20% damage
17 Light flickers
"""


def _table(text: str) -> dict[int, str]:
    rows = (line.split(" ", 1) for line in text.strip().splitlines())
    return {int(number): name for number, name in rows}


LINE_SPECIALS = _table(_LINES)
SECTOR_SPECIALS = _table(_SECTORS)


def line_special_name(number: int) -> str:
    if number == 0:
        return "none"
    return LINE_SPECIALS.get(number, f"unknown ({number})")


def sector_special_name(number: int) -> str:
    if number == 0:
        return "normal"
    return SECTOR_SPECIALS.get(number, f"unknown ({number})")
