/* plot-script.h -- the gnuplot script of a figure of "chaplygin plot":
   the style and terminal, then (after the data blocks the caller writes)
   the plot commands.  Which data blocks a figure reads, and which columns
   of each, are told here too, for the survey that checks them before
   gnuplot runs. */
#ifndef CHAPLYGIN_TOOLS_PLOT_SCRIPT_H
#define CHAPLYGIN_TOOLS_PLOT_SCRIPT_H

#include <stddef.h>
#include <stdio.h>

typedef enum
{
  FIGURE_PANELS,                /* a run: path, V, Omega, theta, E, H */
  FIGURE_PHASE_SPACE,           /* a discrete run: (S, E/E_f, H) */
  FIGURE_SIGMA4,                /* the sweeps: Fig. 2(a), */
  FIGURE_STABILITY,             /* Fig. 2(b), */
  FIGURE_BASINS,                /* Fig. 3, */
  FIGURE_ATLAS                  /* the fate map of an atlas */
} figure_kind;

typedef enum
{
  IMAGE_PNG,
  IMAGE_SVG
} image_format;

/* A column a script reads. */
typedef struct
{
  const char *name;             /* NULL: the end of a list */
  int fixed;                    /* on an axis of fixed range (sigma4's
                                   [-3, 3]): any double, off it unseen */
} figure_column;

/* Everything the script says; the numbers are the scene's and the
   library's. */
typedef struct
{
  figure_kind kind;
  const char *heading;          /* the scene's title, else its file name */
  int massless;                 /* lengths in slot lengths */
  int have_skate;               /* $d: the skate (panels, phase-space) */
  int have_smooth;              /* $s: the smooth sleigh */
  int have_collisions;          /* $c: the massless skate per collision */
  int skate_points, smooth_points;  /* 1: one row, drawn as a point */
  int grid;                     /* stability, atlas: a full regular grid
                                   (image) */
  double x_min, x_max, y_min, y_max;  /* sweeps */
  const double *y;              /* sigma4: the y values */
  size_t n_y, nx, ny;
  const double *boundary;       /* basins: the basin boundaries */
  size_t n_boundary;
  figure_column atlas[4];       /* atlas: the columns of its x and y
                                   quantities (named as the CSV names
                                   them), fate (figure_atlas_axes) */
} figure;

/* The style (doc/figures/style.gp) and the terminal of FORMAT. */
void figure_header (FILE *gp, image_format format);

/* The plot commands of F, after its data blocks. */
void figure_script (FILE *gp, const figure *f);

/* F an atlas whose x and y quantities are the columns X and Y of its
   rows (static names: L0, Delta, V, Omega). */
void figure_atlas_axes (figure *f, const char *x, const char *y);

/* The columns the script of F reads of the data block $BLOCK ('d', 'c',
   's'). */
const figure_column *figure_columns (const figure *f, char block);

#endif
