/* plot-script.c -- the gnuplot script of a figure (plot-script.h).

   A scene is data, never code: gnuplot expands backquotes (a shell
   command), @ macros and reads files named in strings, and a string can
   end a command.  The only text of a scene that reaches the script is its
   title (or, without one, its file name), written by gp_string as a
   double-quoted string in which every byte but letters, digits, space and
   ".,:;()+=/-" is an octal escape (\ooo), drawn without enhanced-text
   markup: no quote, backquote, @, $ or backslash of the scene is ever in
   the script.  Data reach gnuplot as numbers and the program's own column
   names; no file name of the user is in the script (the image goes to
   gnuplot's standard output).

   Figures:
     panels: (a) the path in the plane (the slot front of a skate, pegs +;
       the massless skate's mass centre after each collision, o; the
       smooth skate's contact point), then V, Omega, theta, E, H against
       time; a discrete scene with a smooth companion has both (the smooth
       one dashed);
     phase-space: the (S, E/E_f, H) curves of Figures 4, 5 (S the distance
       the slot travels over its pegs, E_f the last E);
     sweeps: sigma4 against x per y (Fig. 2(a)), the stability regions
       (Fig. 2(b)), the fates against V+ with the basin boundaries (Fig. 3),
       an atlas's fate map: its points coloured by fate (forward,
       backward, spin, undecided, or failed: a status not SUCCESS, no
       fate), the five in the key whether or not the data have them.
   A run of one row is drawn as a point (a line needs two).  Lengths are
   in units of rho (discrete, smooth) or of the slot length (massless), as
   the axis labels say. */
#include <config.h>

#include <math.h>
#include <string.h>

#include "plot-script.h"
#include "plot-style.h"

/* How a run of one row, and one of more, is drawn. */
#define ONE_ROW "points pt 7 ps 0.8"
#define ROWS "lines"

/* TEXT as a gnuplot double-quoted string: letters, digits, space and
   ".,:;()+=/-" as they are, every other byte as \ooo. */
static void
gp_string (FILE *gp, const char *text)
{
  static const char plain[] = " .,:;()+=/-";
  fputc ('"', gp);
  for (const unsigned char *p = (const unsigned char *) text; *p; p++)
    {
      if ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z')
          || (*p >= '0' && *p <= '9') || strchr (plain, *p))
        fputc (*p, gp);
      else
        fprintf (gp, "\\%03o", *p);
    }
  fputc ('"', gp);
}

void
figure_header (FILE *gp, image_format format)
{
  fputs (plot_style, gp);
  fputs ("set encoding utf8\n", gp);
  if (format == IMAGE_SVG)
    fputs ("set terminal svg size 1200,760 font 'DejaVu Sans,10' "
           "linewidth 1.3 background rgb 'white'\n", gp);
}

/* The columns each figure reads of its data blocks (the names in the
   scripts below). */
static const figure_column panels_skate[] = {
  { "x", 0 }, { "y", 0 }, { "peg_x", 0 }, { "peg_y", 0 }, { "tau", 0 },
  { "V", 0 }, { "Omega", 0 }, { "theta", 0 }, { "E", 0 }, { "H", 0 },
  { NULL, 0 } };
static const figure_column panels_collisions[] = {
  { "G_x", 0 }, { "G_y", 0 }, { NULL, 0 } };
static const figure_column panels_smooth[] = {
  { "x", 0 }, { "y", 0 }, { "tau", 0 }, { "V", 0 }, { "Omega", 0 },
  { "theta", 0 }, { "E", 0 }, { "H", 0 }, { NULL, 0 } };
static const figure_column phase_skate[] = {
  { "n", 0 }, { "D", 0 }, { "E", 0 }, { "H", 0 }, { NULL, 0 } };
static const figure_column phase_smooth[] = {
  { "S", 0 }, { "E", 0 }, { "H", 0 }, { NULL, 0 } };
static const figure_column sigma4_sweep[] = {
  { "x", 0 }, { "y", 0 }, { "sigma4", 1 }, { NULL, 0 } };
static const figure_column stability_sweep[] = {
  { "x", 0 }, { "y", 0 }, { "region", 0 }, { NULL, 0 } };
static const figure_column basins_sweep[] = {
  { "V0", 0 }, { "fate", 0 }, { NULL, 0 } };
static const figure_column none[] = { { NULL, 0 } };

void
figure_atlas_axes (figure *f, const char *x, const char *y)
{
  const figure_column atlas[4] = { { x, 0 }, { y, 0 }, { "fate", 0 },
                                   { NULL, 0 } };
  memcpy (f->atlas, atlas, sizeof atlas);
}

const figure_column *
figure_columns (const figure *f, char block)
{
  switch (f->kind)
    {
    case FIGURE_PANELS:
      return block == 'd' ? panels_skate : block == 'c' ? panels_collisions
        : block == 's' ? panels_smooth : none;
    case FIGURE_PHASE_SPACE:
      return block == 'd' ? phase_skate : block == 's' ? phase_smooth : none;
    case FIGURE_SIGMA4:
      return block == 'd' ? sigma4_sweep : none;
    case FIGURE_STABILITY:
      return block == 'd' ? stability_sweep : none;
    case FIGURE_BASINS:
      return block == 'd' ? basins_sweep : none;
    case FIGURE_ATLAS:
      return block == 'd' && f->atlas[0].name ? f->atlas : none;
    }
  return none;
}

/* The path panel (a) of F. */
static void
path_panel (FILE *gp, const figure *f)
{
  const char *len = f->massless ? " (slot lengths)" : "/ρ";
  fprintf (gp, "set title '(a) path%s'; set size ratio -1\n",
           f->have_skate ? "" : " of the contact point C");
  fprintf (gp, "set xlabel 'x%s'; set ylabel 'y%s'\n", len, len);
  fputs ("set key below horizontal samplen 2 spacing 0.9\nplot ", gp);
  if (f->have_skate)
    {
      fprintf (gp, "$d using 'x':'y' with %s @discrete title 'slot front', "
               "$d using 'peg_x':'peg_y' with points pt 1 ps 1.2 "
               "lc rgb 'black' title 'pegs'",
               f->skate_points ? ONE_ROW : ROWS);
      if (f->have_collisions)
        fputs (", $c using 'G_x':'G_y' with linespoints pt 6 ps 1 dt 3 "
               "lc rgb '#c0392b' title 'mass centre G'", gp);
      if (f->have_smooth)
        fputs (", ", gp);
    }
  if (f->have_smooth)
    fprintf (gp, "$s using 'x':'y' with %s %s title '%s'",
             f->smooth_points ? ONE_ROW : ROWS,
             f->have_skate ? "@smooth" : "@discrete",
             f->have_skate ? "smooth skate: C" : "contact point C");
  fputs ("\nunset key; set size noratio; set xlabel 'τ'\n", gp);
}

/* The panels of a run: $d the skate, $c the massless skate per
   collision, $s the smooth sleigh (the scene itself, or the companion). */
static void
panels_script (FILE *gp, const figure *f)
{
  static const char *const quantity[5][3] = {
    { "V", "V", "V" },
    { "Omega", "Ω", "Ω" },
    { "theta", "θ", "θ (rad)" },
    { "E", "E", "E" },
    { "H", "H", "H" }
  };
  const char *first = f->have_skate ? "$d" : "$s";
  int first_points = f->have_skate ? f->skate_points : f->smooth_points;

  fputs ("set multiplot layout 2,3 title ", gp);
  gp_string (gp, f->heading);
  fputs (" noenhanced\n", gp);
  path_panel (gp, f);
  for (int i = 0; i < 5; i++)
    {
      const char *about = "";
      if (i == 4)
        about = !f->have_skate ? " (about C)" : f->have_smooth
          ? " (discrete: about the peg; smooth: about C)"
          : " (about the peg)";
      fprintf (gp, "set title '(%c) %s%s'; set ylabel '%s'\n", 'b' + i,
               quantity[i][1], about, quantity[i][2]);
      fprintf (gp, "plot %s using 'tau':'%s' with %s @discrete", first,
               quantity[i][0], first_points ? ONE_ROW : ROWS);
      if (f->have_skate && f->have_smooth)
        fprintf (gp, ", $s using 'tau':'%s' with %s @smooth",
                 quantity[i][0], f->smooth_points ? ONE_ROW : ROWS);
      fputc ('\n', gp);
    }
  fputs ("unset multiplot\n", gp);
}

/* The (S, E/E_f, H) curves of the run $d (and the smooth $s). */
static void
phase_space_script (FILE *gp, const figure *f)
{
  fputs ("stats $d using (Ef = column('E')) nooutput\n", gp);
  if (f->have_smooth)
    fputs ("stats $s using 'E' every ::0::0 nooutput; Es = STATS_max\n", gp);
  fputs ("set title ", gp);
  gp_string (gp, f->heading);
  fprintf (gp, " noenhanced\n"
           "set xlabel 'S'; set ylabel 'E/E_f'; set zlabel 'H' rotate\n"
           "set view 60, 30; set key top left\n"
           /* S: the slot's travel over its pegs, |dD| summed within a
              segment (D jumps at a collision, S does not) */
           "S = 0; np = -1; Dp = 0\n"
           "splot $d using (n = column('n'), D = column('D'), "
           "S = (n == np ? S + abs(D - Dp) : S), np = n, Dp = D, S)"
           ":(column('E')/Ef):'H' with %s @discrete title "
           "'discrete skate'", f->skate_points ? ONE_ROW : ROWS);
  if (f->have_smooth)
    fprintf (gp, ", $s using 'S':(column('E')/Es):'H' with %s @smooth "
             "title 'smooth skate'", f->smooth_points ? ONE_ROW : ROWS);
  fputc ('\n', gp);
}

/* Fig. 2(a): sigma4 of $d against x, one curve per y. */
static void
sigma4_script (FILE *gp, const figure *f)
{
  fprintf (gp, "array Y[%zu]\n", f->n_y);
  for (size_t i = 0; i < f->n_y; i++)
    fprintf (gp, "Y[%zu] = %.17g\n", i + 1, f->y[i]);
  fprintf (gp, "set xlabel 'L_0/Δ'; set ylabel 'σ_4'\n"
           "set yrange [-3:3]; set key top left\n"
           "plot for [i = 1:|Y|] $d using 'x':(column('y') == Y[i] ? "
           "column('sigma4') : NaN) with %s lw 1.5 title "
           "sprintf('(1/Δ)^2 = %%g', Y[i]), "
           "1 with lines dt 3 lc rgb 'black' notitle, "
           "-1 with lines dt 3 lc rgb 'black' notitle\n",
           f->nx >= 2 ? ROWS : ONE_ROW);
}

/* Fig. 2(b): the stability regions of $d, an image on a full grid (the
   axes its ranges; a single y: gnuplot's). */
static void
stability_script (FILE *gp, const figure *f)
{
  fprintf (gp, "set xrange [%.17g:%.17g]\n", f->x_min, f->x_max);
  if (f->y_min < f->y_max)
    fprintf (gp, "set yrange [%.17g:%.17g]\n", f->y_min, f->y_max);
  fputs ("set xlabel 'L_0/Δ'; set ylabel '(1/Δ)^2'\n"
         "set palette defined (0 'white', 1 '#b0b0b0', 2 '#7fa7d9', "
         "3 '#2c4f7c')\n"
         "set cbrange [-0.5:3.5]; set palette maxcolors 4\n"
         "set cbtics ('unstable' 0, 'V*>0 stable' 1, 'V*<0 stable' 2, "
         "'both' 3)\n", gp);
  if (f->grid)
    fputs ("plot $d using 'x':'y':'region' with image\n", gp);
  else
    fputs ("plot $d using 'x':'y':'region' with points pt 5 ps 2 "
           "lc palette\n", gp);
}

/* Fig. 3: the fates of $d against V+, the basin boundaries dotted. */
static void
basins_script (FILE *gp, const figure *f)
{
  fputs ("set xlabel 'initial V^+'; set ylabel 'fate'\n"
         "set ytics ('V* < 0' -1, 'spin' 0, 'V* > 0' 1, 'undecided' 2)\n"
         "stats $d using 'fate' nooutput\n"
         "set yrange [-1.5:(STATS_max > 1 ? 2.5 : 1.5)]\n", gp);
  for (size_t i = 0; i < f->n_boundary; i++)
    fprintf (gp, "set arrow from %.17g, graph 0 to %.17g, graph 1 "
             "nohead dt 3 lc rgb '#888888'\n", f->boundary[i],
             f->boundary[i]);
  fputs ("plot $d using 'V0':'fate' with points pt 7 ps 0.3 "
         "lc rgb '#1f3b73'\n", gp);
}

/* The axis label of an atlas's quantity NAME (a column name). */
static const char *
atlas_label (const char *name)
{
  static const char *const label[][2] = {
    { "L0", "L_0" }, { "Delta", "Δ" }, { "V", "initial V^+" },
    { "Omega", "initial Ω^+" } };
  for (size_t i = 0; i < sizeof label / sizeof label[0]; i++)
    if (strcmp (name, label[i][0]) == 0)
      return label[i][1];
  return "";
}

/* Half the spacing of the N points of a sweep's grid from LO to HI (LO
   <= HI); the half-width of a cell.  One point, or LO = HI: a cell of
   the range, else of half its magnitude (1/2 at 0), at most 1e300. */
static double
half_cell (double lo, double hi, size_t n)
{
  double h = n >= 2 ? (hi / 2 - lo / 2) / (double) (n - 1) : hi / 2 - lo / 2;
  if (lo == hi)
    h = lo != 0 ? fabs (lo) / 2 : 0.5;
  return h <= 1e300 ? h : 1e300;
}

/* An atlas's fate map: each point of $d coloured by its class, its fate
   (-1 backward, 0 spin, 1 forward, 2 undecided) where its status is
   SUCCESS, else failed (its fate cell is empty).  On a full grid
   (f->grid) an image of a pixel per point; one x, one y, or y_min = y_max
   (gnuplot's image needs a grid of 2 x 2) boxes of the grid's spacing, the
   first row only where every row is the same y.  The five classes are in
   the key whether or not the data have them. */
static void
atlas_script (FILE *gp, const figure *f)
{
  /* by class: fate + 2 (gnuplot's arrays from 1), failed 5; the
     Okabe-Ito colours, told apart also by colour-blind eyes */
  static const struct
  {
    unsigned rgb;
    const char *title;
  } class[5] = {
    { 0xd55e00, "backward (V* < 0)" }, { 0x009e73, "spin" },
    { 0x0072b2, "forward (V* > 0)" }, { 0xf0e442, "undecided" },
    { 0x000000, "failed (status not SUCCESS)" } };
  static const int key_order[5] = { 2, 0, 1, 3, 4 };
  const char *x = f->atlas[0].name, *y = f->atlas[1].name;
  fprintf (gp, "set xlabel '%s'; set ylabel '%s'\n", atlas_label (x),
           atlas_label (y));
  fputs ("array C[5] = [", gp);
  for (int i = 0; i < 5; i++)
    fprintf (gp, "%s0x%06x", i ? ", " : "", class[i].rgb);
  fputs ("]\n"
         "set autoscale xfix; set autoscale yfix; set tics out; "
         "set grid noxtics noytics; set border front\n"
         "set key outside right top vertical Left reverse samplen 1.5 "
         "title 'fate' noenhanced\n", gp);
  /* the class's colour of the row: strcol('status') is read first, so the
     empty fate of a failed point is never read */
  const char *colour = "(C[strcol('status') eq 'SUCCESS' ? "
    "int(column('fate')) + 2 : 5])";
  if (f->grid)
    fprintf (gp, "plot $d using '%s':'%s':(c = %s, (c >> 16) & 255):"
             "((c >> 8) & 255):(c & 255) with rgbimage", x, y, colour);
  else
    {
      fprintf (gp, "plot $d using '%s':'%s':(%.17g):(%.17g):%s", x, y,
               half_cell (f->x_min, f->x_max, f->nx),
               half_cell (f->y_min, f->y_max, f->ny), colour);
      if (f->y_min == f->y_max)
        fprintf (gp, " every ::0::%zu", f->nx - 1);
      fputs (" with boxxyerror lc rgb variable fs solid 1.0 border", gp);
    }
  for (int i = 0; i < 5; i++)
    fprintf (gp, ", keyentry with boxes fs solid 1.0 lc rgb '#%06x' "
             "title '%s'", class[key_order[i]].rgb, class[key_order[i]].title);
  fputc ('\n', gp);
}

void
figure_script (FILE *gp, const figure *f)
{
  if (f->kind == FIGURE_PANELS)
    {
      panels_script (gp, f);
      return;
    }
  if (f->kind == FIGURE_PHASE_SPACE)
    {
      phase_space_script (gp, f);
      return;
    }
  fputs ("set title ", gp);
  gp_string (gp, f->heading);
  fputs (" noenhanced\n", gp);
  if (f->kind == FIGURE_SIGMA4)
    sigma4_script (gp, f);
  else if (f->kind == FIGURE_STABILITY)
    stability_script (gp, f);
  else if (f->kind == FIGURE_BASINS)
    basins_script (gp, f);
  else
    atlas_script (gp, f);
}
