/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: named granular materials read from a potential-style file.
------------------------------------------------------------------------- */

#include "gransph_material.h"

#include "comm.h"
#include "error.h"
#include "math_const.h"
#include "potential_file_reader.h"
#include "tokenizer.h"

#include <algorithm>
#include <cmath>
#include <iterator>

using namespace LAMMPS_NS;

namespace {
constexpr int NPARAMS = 11;    // name + 10 numbers per material line

void check(LAMMPS *lmp, bool ok, const std::string &style, const GranSPHMaterial &m,
           const char *what)
{
  if (!ok) lmp->error->all(FLERR, "{}: material {}: {}", style, m.name, what);
}
}    // namespace

GranSPHMaterial GranSPHMaterial::read(LAMMPS *lmp, const std::string &file,
                                      const std::string &name, const std::string &style)
{
  GranSPHMaterial m;
  m.name = name;
  double values[NPARAMS - 1] = {0.0};
  int found = 0;

  // every line is one whole material: a field too many or too few is an error, not
  // a value silently dropped or taken from the next line
  if (lmp->comm->me == 0) {
    PotentialFileReader reader(lmp, file, "GRANSPH material");
    char *line;
    while ((line = reader.next_line())) {
      const std::string text = utils::trim(line);
      ValueTokenizer words(text);
      const std::string material = words.next_string();
      if (words.count() != NPARAMS)
        lmp->error->one(FLERR, "{}: material file {}, material {}: {} fields instead of {} "
                        "on line: {}", style, file, material, words.count(), NPARAMS, text);
      try {
        double line_values[NPARAMS - 1];
        for (double &v : line_values) v = words.next_double();
        if (material != name || found) continue;
        std::copy(std::begin(line_values), std::end(line_values), values);
        found = 1;
      } catch (TokenizerException &e) {
        lmp->error->one(FLERR, "{}: material file {}, material {}: {} on line: {}", style, file,
                        material, e.what(), text);
      }
    }
  }
  MPI_Bcast(&found, 1, MPI_INT, 0, lmp->world);
  if (!found) lmp->error->all(FLERR, "{}: material {} not found in file {}", style, name, file);
  MPI_Bcast(values, NPARAMS - 1, MPI_DOUBLE, 0, lmp->world);

  const double deg = MathConst::MY_PI / 180.0;
  m.rho0 = values[0];
  m.E = values[1];
  m.nu = values[2];
  m.phi = values[3] * deg;
  m.psi = values[4] * deg;
  m.c = values[5];
  m.rho_c = values[6];
  m.xi = values[7];
  m.mu_s = values[8];
  m.mu_2 = values[9];

  check(lmp, m.rho0 > 0.0, style, m, "rho0 must be > 0");
  check(lmp, m.E > 0.0, style, m, "Young's modulus E must be > 0");
  check(lmp, m.nu > -1.0 && m.nu < 0.5, style, m, "Poisson's ratio must be in (-1, 0.5)");
  check(lmp, m.phi >= 0.0 && m.phi < 0.5 * MathConst::MY_PI, style, m,
        "friction angle must be in [0, 90) degrees");
  check(lmp, m.psi >= 0.0 && m.psi <= m.phi, style, m,
        "dilatancy angle must be in [0, friction angle]");
  check(lmp, m.c >= 0.0, style, m, "cohesion must be >= 0");
  check(lmp, m.rho_c >= 0.0, style, m, "critical density rho_c must be >= 0");
  check(lmp, m.xi >= 0.0, style, m, "xi must be >= 0");
  check(lmp, m.mu_s >= 0.0 && m.mu_2 >= m.mu_s, style, m, "need 0 <= mu_s <= mu_2");
  return m;
}
