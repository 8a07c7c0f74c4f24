/* ----------------------------------------------------------------------
   GRANSPH plugin: registers every GRANSPH style with LAMMPS.
   Load it with "plugin load gransphplugin.so".
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "fix_sph_elastoplastic.h"
#include "fix_sph_phasechange.h"
#include "pair_sph_granular.h"

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
}
