/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH plugin: registers every GRANSPH style with LAMMPS.
   Load it with "plugin load gransphplugin.so".
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "compute_sph_material_atom.h"
#include "compute_sph_runout.h"
#include "compute_sph_stress_atom.h"
#include "compute_sph_visc_atom.h"
#include "compute_sph_wallforce.h"
#include "fix_sph_inflow.h"
#include "fix_sph_models.h"
#include "fix_sph_move.h"
#include "fix_sph_normals.h"
#include "fix_sph_outflow.h"
#include "pair_sph_granular.h"

#include "compute_sph_wallforce_kokkos.h"
#include "fix_sph_inflow_kokkos.h"
#include "fix_sph_model_kokkos.h"
#include "fix_sph_move_kokkos.h"
#include "pair_sph_granular_kokkos.h"

using namespace LAMMPS_NS;

namespace {

template <class T> Pair *pair_creator(LAMMPS *lmp)
{
  return new T(lmp);
}

template <class T> Fix *fix_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new T(lmp, argc, argv);
}

template <class T> Compute *compute_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new T(lmp, argc, argv);
}

void register_style(lammpsplugin_regfunc register_plugin, void *lmp, void *handle,
                    const char *style, const char *name, const char *info, void *creator,
                    bool is_v2)
{
  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = style;
  plugin.name = name;
  plugin.info = info;
  plugin.author = "GRANSPH developers";
  if (is_v2)
    plugin.creator.v2 = (lammpsplugin_factory2 *) creator;
  else
    plugin.creator.v1 = (lammpsplugin_factory1 *) creator;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);
}

// the Kokkos twins of a style: name/kk and name/kk/device run on the Kokkos
// device, name/kk/host on the host execution space
struct KokkosNames {
  const char *kk, *device, *host;
};
// their names from the style's, as string literals: LAMMPS keeps the pointers
#define GRANSPH_KOKKOS_NAMES(name) {name "/kk", name "/kk/device", name "/kk/host"}

void register_kokkos_style(lammpsplugin_regfunc reg, void *lmp, void *handle, const char *style,
                           const KokkosNames &names, const char *info, void *device_creator,
                           void *host_creator, bool is_v2)
{
  register_style(reg, lmp, handle, style, names.kk, info, device_creator, is_v2);
  register_style(reg, lmp, handle, style, names.device, info, device_creator, is_v2);
  register_style(reg, lmp, handle, style, names.host, info, host_creator, is_v2);
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto reg = (lammpsplugin_regfunc) regfunc;
  register_style(reg, lmp, handle, "pair", "sph/granular",
                 "GRANSPH granular SPH pair style (Chen et al. 2019)",
                 (void *) &pair_creator<PairSPHGranular>, false);
  register_style(reg, lmp, handle, "fix", "sph/elastoplastic",
                 "GRANSPH integrator, Drucker-Prager elastoplastic model",
                 (void *) &fix_creator<FixSPHElastoplastic>, true);
  register_style(reg, lmp, handle, "fix", "sph/phasechange",
                 "GRANSPH integrator, Dunatunga-Kamrin phase-change model",
                 (void *) &fix_creator<FixSPHPhaseChange>, true);
  register_style(reg, lmp, handle, "fix", "sph/inflow",
                 "GRANSPH: granular nozzle inserting layers of particles",
                 (void *) &fix_creator<FixSPHInflow>, true);
  register_style(reg, lmp, handle, "fix", "sph/move",
                 "GRANSPH: walls moved with a prescribed velocity at any timestep",
                 (void *) &fix_creator<FixSPHMove>, true);
  register_style(reg, lmp, handle, "fix", "sph/outflow",
                 "GRANSPH: delete particles that leave a region",
                 (void *) &fix_creator<FixSPHOutflow>, true);
  register_style(reg, lmp, handle, "fix", "sph/normals",
                 "GRANSPH: the dummy particles' own wall normals",
                 (void *) &fix_creator<FixSPHNormals>, true);
  register_style(reg, lmp, handle, "compute", "sph/wallforce",
                 "GRANSPH: force of the grains on a wall of dummy particles",
                 (void *) &compute_creator<ComputeSPHWallForce>, true);
  register_style(reg, lmp, handle, "compute", "sph/stress/atom",
                 "GRANSPH: per-atom p, q, principal stresses, Lode angle, mobilised strength",
                 (void *) &compute_creator<ComputeSPHStressAtom>, true);
  register_style(reg, lmp, handle, "compute", "sph/visc/atom",
                 "GRANSPH: per-atom pressure of the artificial viscosity",
                 (void *) &compute_creator<ComputeSPHViscAtom>, true);
  register_style(reg, lmp, handle, "compute", "sph/material/atom",
                 "GRANSPH: per-atom material of the grains",
                 (void *) &compute_creator<ComputeSPHMaterialAtom>, true);
  register_style(reg, lmp, handle, "compute", "sph/runout",
                 "GRANSPH: deposit edge, skirt and height from the thickness profile",
                 (void *) &compute_creator<ComputeSPHRunout>, true);

  register_kokkos_style(reg, lmp, handle, "pair", GRANSPH_KOKKOS_NAMES("sph/granular"),
                        "GRANSPH granular SPH pair style, Kokkos",
                        (void *) &pair_creator<PairSPHGranularKokkos<LMPDeviceType>>,
                        (void *) &pair_creator<PairSPHGranularKokkos<LMPHostType>>, false);
  register_kokkos_style(
      reg, lmp, handle, "fix", GRANSPH_KOKKOS_NAMES("sph/elastoplastic"),
      "GRANSPH integrator, Drucker-Prager elastoplastic model, Kokkos",
      (void *) &fix_creator<FixSPHModelKokkos<LMPDeviceType, GRANSPH::DruckerPrager>>,
      (void *) &fix_creator<FixSPHModelKokkos<LMPHostType, GRANSPH::DruckerPrager>>, true);
  register_kokkos_style(
      reg, lmp, handle, "fix", GRANSPH_KOKKOS_NAMES("sph/phasechange"),
      "GRANSPH integrator, Dunatunga-Kamrin phase-change model, Kokkos",
      (void *) &fix_creator<FixSPHModelKokkos<LMPDeviceType, GRANSPH::PhaseChange>>,
      (void *) &fix_creator<FixSPHModelKokkos<LMPHostType, GRANSPH::PhaseChange>>, true);
  register_kokkos_style(reg, lmp, handle, "compute", GRANSPH_KOKKOS_NAMES("sph/wallforce"),
                        "GRANSPH: force of the grains on a wall of dummy particles, Kokkos",
                        (void *) &compute_creator<ComputeSPHWallForceKokkos<LMPDeviceType>>,
                        (void *) &compute_creator<ComputeSPHWallForceKokkos<LMPHostType>>, true);
  register_kokkos_style(reg, lmp, handle, "fix", GRANSPH_KOKKOS_NAMES("sph/inflow"),
                        "GRANSPH: granular nozzle, Kokkos (inserts on the host)",
                        (void *) &fix_creator<FixSPHInflowKokkos>,
                        (void *) &fix_creator<FixSPHInflowKokkos>, true);
  register_kokkos_style(reg, lmp, handle, "fix", GRANSPH_KOKKOS_NAMES("sph/move"),
                        "GRANSPH: walls moved with a prescribed velocity, Kokkos",
                        (void *) &fix_creator<FixSPHMoveKokkos<LMPDeviceType>>,
                        (void *) &fix_creator<FixSPHMoveKokkos<LMPHostType>>, true);
}
