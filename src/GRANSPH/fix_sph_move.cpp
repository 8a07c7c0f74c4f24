/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: fix sph/move.

   The GRANSPH integrator advances the grains half a step in initial_integrate
   and evaluates the pair at the mid-point, so the walls must be there too:
   this fix moves them half a step in initial_integrate and the other half in
   final_integrate. With the prescribed velocity u_n at the start of the step
   and u_n+1 at its end, the mid-point x_n + dt/2 (3 u_n + u_n+1)/4 and the
   end point x_n + dt (u_n + u_n+1)/2 are exact for a velocity linear in time,
   and the walls carry the mid-point velocity when the pair runs. Unlike fix
   move, this works with the integrator's adaptive (CFL) timestep.
------------------------------------------------------------------------- */

#include "fix_sph_move.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_integrate.h"
#include "gransph_find_fix.h"
#include "group.h"
#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID group sph/move vx vy vz    (each a number or v_name)
------------------------------------------------------------------------- */

FixSPHMove::FixSPHMove(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  if (narg != 6) error->all(FLERR, "Illegal fix sph/move command: expected vx vy vz");
  for (int a = 0; a < 3; ++a) {
    Component &c = component[a];
    c.value = 0.0;
    c.variable = nullptr;
    c.ivariable = -1;
    if (utils::strmatch(arg[3 + a], "^v_"))
      c.variable = utils::strdup(arg[3 + a] + 2);
    else
      c.value = utils::numeric(FLERR, arg[3 + a], false, lmp);
  }
  if (domain->dimension == 2 && (component[2].variable || component[2].value != 0.0))
    error->all(FLERR, "Fix sph/move: vz must be 0 for a 2d simulation");
  time_integrate = 1;
  for (int a = 0; a < 3; ++a) u_start[a] = u_end[a] = 0.0;
}

FixSPHMove::~FixSPHMove()
{
  for (Component &c : component) delete[] c.variable;
}

int FixSPHMove::setmask()
{
  return INITIAL_INTEGRATE | FINAL_INTEGRATE | PRE_FORCE;
}

void FixSPHMove::init()
{
  for (Component &c : component) {
    if (!c.variable) continue;
    c.ivariable = input->variable->find(c.variable);
    if (c.ivariable < 0) error->all(FLERR, "Fix sph/move: variable {} does not exist", c.variable);
    if (!input->variable->equalstyle(c.ivariable))
      error->all(FLERR, "Fix sph/move: variable {} is not equal-style", c.variable);
  }
  check_not_granular();
}

// the atoms the GRANSPH integrator integrates must not be moved by this fix too
void FixSPHMove::check_not_granular() const
{
  const FixSPHIntegrate &integrator = FixSPHIntegrate::find(lmp, "Fix sph/move");
  const int *mask = atom->mask;
  const int integrated = integrator.groupbit;
  const auto granular = [&](int i) { return (mask[i] & groupbit) && (mask[i] & integrated); };
  if (GRANSPH::any_owned_atom(lmp, granular))
    error->all(FLERR, "Fix sph/move: group {} has atoms that fix {} integrates",
               group->names[igroup], integrator.id);
}

void FixSPHMove::evaluate(double *u)
{
  for (int a = 0; a < 3; ++a) {
    const Component &c = component[a];
    u[a] = c.variable ? input->variable->compute_equal(c.ivariable) : c.value;
  }
}

// before the setup's pair evaluation: the walls, and their ghosts, get the velocity
// of the start
void FixSPHMove::setup_pre_force(int)
{
  evaluate(u_start);
  const double none[3] = {0.0, 0.0, 0.0};
  move(none, u_start);
  comm->forward_comm();
}

// in a step, variables see the time at its end
void FixSPHMove::initial_integrate(int)
{
  evaluate(u_end);
  const double half = 0.5 * update->dt;
  double dx[3], v[3];
  for (int a = 0; a < 3; ++a) {
    dx[a] = half * 0.25 * (3.0 * u_start[a] + u_end[a]);
    v[a] = 0.5 * (u_start[a] + u_end[a]);
  }
  move(dx, v);
}

void FixSPHMove::final_integrate()
{
  const double half = 0.5 * update->dt;
  double dx[3];
  for (int a = 0; a < 3; ++a) {
    dx[a] = half * 0.25 * (u_start[a] + 3.0 * u_end[a]);
    u_start[a] = u_end[a];
  }
  move(dx, u_end);
}

void FixSPHMove::move(const double *dx, const double *v)
{
  double **x = atom->x, **vel = atom->v;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    for (int a = 0; a < 3; ++a) {
      x[i][a] += dx[a];
      vel[i][a] = v[a];
    }
  }
}
