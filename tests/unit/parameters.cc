// The parameters bound to the modules' structs (core/parameters.h) against
// what deal.II's ParameterHandler holds, and the reading of moved entries
// (base/parameter_file.h). Exact answers: each value read must land in its
// member, each entry must print as it was read.
//  - The defaults of the members are the defaults ParameterHandler prints,
//    and the default scene passes check().
//  - A file setting every entry to a non-default value: the members hold
//    those values, and printing the handler and reading the print into a
//    fresh Parameters gives the same print (every entry bound both ways).
//  - Every moved entry set at its old place lands in its new member, with
//    one warning naming both places; old and new place together are refused.
//  - 'automatic' entries resolve by the material's regime or, for the
//    stress interpolation, by the velocity interpolation; the new force
//    weight by the time scheme; the level set interpolation by the
//    dimension, a prescribed velocity and the band placement; the velocity
//    interpolation by the regime and the band placement; the remap distance by
//    the level set interpolation, a prescribed velocity and the band placement;
//    the band width and miss tolerance by the band placement; the band
//    placement by the strain bound, the target CFL and the interpolation at the
//    feet.

#include "unit_test.h"

#include <vefs/base/errors.h>
#include <vefs/core/parameters.h>

#include <fstream>
#include <iostream>
#include <sstream>

using namespace dealii;

namespace
{
  std::string
  printed(const ParameterHandler &prm)
  {
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::PRM);
    return text.str();
  }

  void
  write(const std::string &file, const std::string &text)
  {
    std::ofstream(file) << text;
  }

  /** Read @p file into @p parameters as vefs does and check them (throws
   * vefs::InputError). */
  void
  read_and_check(vefs::Parameters &parameters, const std::string &file)
  {
    ParameterHandler prm;
    parameters.declare(prm);
    vefs::read_parameter_file(prm, file, vefs::Parameters::moved_entries);
    parameters.check();
  }

  void
  report(std::ostream &out, const std::string &label, const bool passed)
  {
    out << label << ": " << (passed ? "yes" : "NO") << '\n';
  }
} // namespace

int
main()
{
  std::ostream &out = std::cout;

  {
    vefs::Parameters parameters;
    ParameterHandler prm;
    parameters.declare(prm);
    // What the members hold must be what the handler says.
    report(out,
           "defaults: members equal the handler's values",
           std::stod(prm.get({"Time"}, "End time")) ==
               parameters.time.end_time &&
             prm.get({"Mesh refinement"}, "Band placement") == "automatic" &&
             parameters.mesh.band_placement == vefs::BandPlacement::automatic &&
             (prm.get({"Transport"}, "Volume correction") == "true") ==
               parameters.transport.volume_correction &&
             prm.get({"Walls"}, "y+") == "open" &&
             parameters.cavity.wall_type[3] == vefs::WallType::open &&
             prm.get("Gravity") == "0, -9.81");
    bool passed = true;
    try
      {
        parameters.check();
      }
    catch (const vefs::InputError &)
      {
        passed = false;
      }
    report(out, "defaults: the default scene passes check()", passed);
  }

  {
    const std::string scene = "subsection Time\n"
                              "  set End time = 0.5\n"
                              "  set Strain bound = local\n"
                              "  set Maximum strain per step = 0.1\n"
                              "end\n"
                              "subsection Mesh refinement\n"
                              "  set Band placement = predicted, one change\n"
                              "  set Maximum level = 5\n"
                              "end\n"
                              "subsection Walls\n"
                              "  set y- = contact\n"
                              "end\n"
                              "subsection Stress\n"
                              "  set Stress update = exponential\n"
                              "end\n"
                              "subsection Flow\n"
                              "  set Outside stress of cut cells = extension\n"
                              "end\n"
                              "subsection Postprocess\n"
                              "  set Probe point = 0.1, 0.05\n"
                              "end\n";
    write("scene.prm", scene);
    vefs::Parameters parameters;
    ParameterHandler prm;
    parameters.declare(prm);
    const auto warnings =
      vefs::read_parameter_file(prm,
                                "scene.prm",
                                vefs::Parameters::moved_entries);
    report(out,
           "a scene: every value in its member",
           warnings.empty() && parameters.time.end_time == 0.5 &&
             !parameters.time.strain_bound_shortens_step &&
             parameters.mesh.band_in_one_change() &&
             parameters.mesh.max_level == 5 &&
             parameters.cavity.wall_type[2] == vefs::WallType::contact &&
             parameters.stress.stress_update ==
               vefs::StressUpdate::exponential &&
             parameters.flow.outside_stress == vefs::OutsideStress::extension &&
             parameters.postprocess.probe_point ==
               std::vector<double>({0.1, 0.05}));

    write("printed.prm", printed(prm));
    vefs::Parameters again;
    ParameterHandler prm_again;
    again.declare(prm_again);
    vefs::read_parameter_file(prm_again,
                              "printed.prm",
                              vefs::Parameters::moved_entries);
    report(out,
           "a scene: its print read again prints the same",
           printed(prm_again) == printed(prm) &&
             again.mesh.band_in_one_change() &&
             again.postprocess.probe_point ==
               parameters.postprocess.probe_point);
  }

  {
    // Every moved entry at its old place, with a value that is not its
    // default.
    write("moved.prm",
          "subsection Mesh refinement\n"
          "  set Level set interpolation = gradient augmented\n"
          "  set Velocity interpolation = cubic\n"
          "  set Stress interpolation = limited cubic\n"
          "  set Remap distance = 10\n"
          "  set Redistancing interval = 0\n"
          "  set Volume correction = false\n"
          "  set Flow cells = parents\n"
          "  set Extension layers = 7\n"
          "  set Outside velocity of cut cells = extension\n"
          "  set Outside stress of cut cells = extension\n"
          "end\n"
          "subsection Solver\n"
          "  set Stress update = exponential\n"
          "  set Stress theta = 0.5\n"
          "end\n");
    vefs::Parameters parameters;
    ParameterHandler prm;
    parameters.declare(prm);
    const auto warnings =
      vefs::read_parameter_file(prm,
                                "moved.prm",
                                vefs::Parameters::moved_entries);
    const auto &t = parameters.transport;
    const auto &f = parameters.flow;
    report(out,
           "moved entries: each in its new member",
           t.level_set_interpolation ==
               vefs::LevelSetInterpolation::gradient_augmented &&
             t.velocity_interpolation == vefs::VelocityInterpolation::cubic &&
             t.stress_interpolation ==
               vefs::StressInterpolation::limited_cubic &&
             t.remap_distance == 10 && t.redistancing_interval == 0 &&
             !t.volume_correction && f.flow_level_offset == 1 &&
             f.extension_layers == 7 &&
             f.outside_velocity == vefs::OutsideVelocity::extension &&
             f.outside_stress == vefs::OutsideStress::extension &&
             parameters.stress.stress_update ==
               vefs::StressUpdate::exponential &&
             parameters.stress.stress_theta == 0.5 &&
             prm.get({"Transport"}, "Remap distance") == "10");
    out << "moved entries: " << warnings.size() << " warnings, of "
        << vefs::Parameters::moved_entries.size() << " moved entries\n";
    out << "first warning: " << warnings.at(0) << '\n';
  }

  {
    write("twice.prm",
          "subsection Mesh refinement\n"
          "  set Remap distance = 10\n"
          "end\n"
          "subsection Transport\n"
          "  set Remap distance = 3\n"
          "end\n");
    vefs::Parameters parameters;
    ParameterHandler prm;
    parameters.declare(prm);
    try
      {
        vefs::read_parameter_file(prm,
                                  "twice.prm",
                                  vefs::Parameters::moved_entries);
        out << "old and new place: NOT refused\n";
      }
    catch (const vefs::InputError &error)
      {
        out << "old and new place: " << error.what() << '\n';
      }
  }

  {
    // 'automatic' entries take the value of the material's regime; a
    // number given stays.
    const auto resolved = [](const std::string &material,
                             const std::string &time) {
      write("automatic.prm",
            "subsection Material\n" + material + "end\nsubsection Time\n" +
              time + "end\n");
      vefs::Parameters parameters;
      read_and_check(parameters, "automatic.prm");
      return std::string(parameters.stress.stress_update ==
                             vefs::StressUpdate::exponential
                           ? "exponential"
                           : "linear") +
             ", maximum strain per step " +
             std::to_string(parameters.time.max_strain_per_step) +
             ", outside stress " +
             (parameters.flow.extends_outside_stress() ? "extension"
                                                       : "updated");
    };
    const std::string elastic = "  set Alpha = 0\n"
                                "  set Polymer viscosity = 10\n"
                                "  set Relaxation time = 0.005\n";
    const std::string oldroyd = "  set Polymer viscosity = 10\n"
                                "  set Relaxation time = 0.005\n";
    out << "automatic, elastic solid: " << resolved(elastic, "") << '\n';
    out << "automatic, Oldroyd-B liquid: " << resolved(oldroyd, "") << '\n';
    out << "automatic, Newtonian liquid: "
        << resolved("  set Density = 1000\n", "") << '\n';
    out << "elastic solid, strain bound 0.1: "
        << resolved(elastic, "  set Maximum strain per step = 0.1\n") << '\n';
    try
      {
        resolved(elastic, "  set Maximum strain per step = -1\n");
        out << "strain bound -1: NOT refused\n";
      }
    catch (const vefs::InputError &error)
      {
        out << "strain bound -1: " << error.what() << '\n';
      }
  }

  {
    // 'Time/New force weight = automatic': 1/2 for the second-order scheme
    // (a material with a stress), 0.51 if a wall is a contact wall, 1 for
    // the first-order scheme. A number stays with the second-order scheme;
    // it is refused with the first-order one and outside [0.5, 1].
    const auto weight = [](const std::string &material,
                           const std::string &time,
                           const std::string &walls = "") {
      write("weight.prm",
            "subsection Material\n" + material + "end\nsubsection Time\n" +
              time + "end\nsubsection Walls\n" + walls + "end\n");
      try
        {
          vefs::Parameters parameters;
          read_and_check(parameters, "weight.prm");
          std::ostringstream text;
          text << parameters.flow_step().new_force_weight;
          return text.str();
        }
      catch (const vefs::InputError &error)
        {
          return std::string(error.what());
        }
    };
    const std::string elastic = "  set Alpha = 0\n"
                                "  set Polymer viscosity = 10\n"
                                "  set Relaxation time = 0.005\n";
    out << "new force weight automatic, elastic solid: " << weight(elastic, "")
        << '\n';
    out << "the same, a contact floor: "
        << weight(elastic, "", "  set y- = contact\n") << '\n';
    out << "the same, a contact floor, first-order scheme: "
        << weight(elastic,
                  "  set Scheme = first order\n",
                  "  set y- = contact\n")
        << '\n';
    out << "the same, first-order scheme: "
        << weight(elastic, "  set Scheme = first order\n") << '\n';
    out << "the same, Newtonian liquid: "
        << weight("  set Density = 1000\n", "") << '\n';
    for (const std::string value : {"0.5", "1", "0.4", "1.5"})
      out << "new force weight " << value << ", elastic solid: "
          << weight(elastic, "  set New force weight = " + value + "\n")
          << '\n';
    out << "new force weight 0.5, first-order scheme: "
        << weight(elastic,
                  "  set Scheme = first order\n"
                  "  set New force weight = 0.5\n")
        << '\n';
  }

  {
    // 'Stress interpolation = automatic' follows 'Velocity interpolation':
    // limited cubic where the velocity is (limited) cubic, linear otherwise;
    // an explicit value stays.
    const auto stress_interpolation = [](const std::string &transport) {
      write("stress_interpolation.prm",
            "subsection Transport\n" + transport + "end\n");
      vefs::Parameters parameters;
      read_and_check(parameters, "stress_interpolation.prm");
      return std::string(parameters.transport.cubic_stress_interpolation()
                           ? "limited cubic"
                           : "linear");
    };
    for (const std::string velocity : {"linear", "cubic", "limited cubic"})
      out << "stress interpolation automatic, velocity " << velocity << ": "
          << stress_interpolation("  set Velocity interpolation = " + velocity +
                                  "\n")
          << '\n';
    out << "stress interpolation linear, velocity limited cubic: "
        << stress_interpolation("  set Velocity interpolation = limited "
                                "cubic\n  set Stress interpolation = linear\n")
        << '\n';
    out << "stress interpolation limited cubic, velocity linear: "
        << stress_interpolation("  set Stress interpolation = limited cubic\n")
        << '\n';
  }

  {
    // 'Velocity interpolation = automatic': cubic for an elastic
    // solid with the macroscopic stress, the second-order scheme and a
    // weight strain rho |g| L / (3 G) in (0, 1), L the cavity's largest
    // extent, unless the band is placed in one change; linear otherwise.
    // 'Solver/Pressure stabilization = automatic': 0.05 for an elastic
    // solid with the macroscopic stress, the second-order scheme and that
    // weight strain (whatever the band), 0.25 otherwise; 'Flow/Outside
    // velocity of cut cells = automatic' extension and solution, 'Stress/
    // Nodal stress = automatic' lumped increment and vertex average by the
    // same rule. An explicit value stays.
    const auto velocity_interpolation = [](const std::string &top,
                                           const std::string &material,
                                           const std::string &time,
                                           const std::string &transport) {
      write("velocity_interpolation.prm",
            "set Dimension = 2\n" + top + "subsection Material\n" + material +
              "end\nsubsection Time\n" + time + "end\nsubsection Transport\n" +
              transport + "end\n");
      vefs::Parameters parameters;
      read_and_check(parameters, "velocity_interpolation.prm");
      const auto velocity = parameters.transport.velocity_interpolation;
      return std::string(velocity == vefs::VelocityInterpolation::linear
                           ? "linear"
                         : velocity == vefs::VelocityInterpolation::cubic
                           ? "cubic"
                           : "limited cubic") +
             ", stress " +
             (parameters.transport.cubic_stress_interpolation()
                ? "limited cubic"
                : "linear") +
             ", pressure stabilization " +
             std::to_string(parameters.solver.pressure_stabilization)
               .substr(0, 4) +
             ", outside velocity " +
             (parameters.flow.resolved_outside_velocity() ==
                  vefs::OutsideVelocity::extension_at_walls
                ? "extension at walls"
              : parameters.flow.resolved_outside_velocity() ==
                  vefs::OutsideVelocity::extension
                ? "extension"
                : "solution") +
             ", nodal stress " +
             (parameters.stress.nodal_stress ==
                  vefs::NodalStress::lumped_increment
                ? "lumped increment"
                : "vertex average");
    };
    // G = eta_p / lambda; with the defaults rho = 1000, g = 9.81 and the
    // cavity 0.28575 m wide the weight strain is 0.467 at G = 2000 Pa,
    // 0.950 at eta_p = 4.92 and 1.050 at 4.45 Pa s, 46.7 at 20 Pa.
    const auto elastic = [](const std::string &polymer_viscosity) {
      return "  set Alpha = 0\n  set Polymer viscosity = " + polymer_viscosity +
             "\n  set Relaxation time = 0.005\n";
    };
    out << "velocity interpolation automatic, elastic solid, weight strain "
           "0.467: "
        << velocity_interpolation("", elastic("10"), "", "") << '\n';
    out << "the same, weight strain 0.950: "
        << velocity_interpolation("", elastic("4.92"), "", "") << '\n';
    out << "the same, weight strain 1.050: "
        << velocity_interpolation("", elastic("4.45"), "", "") << '\n';
    out << "the same, weight strain 46.7: "
        << velocity_interpolation("", elastic("0.1"), "", "") << '\n';
    out << "the same (0.467), no gravity: "
        << velocity_interpolation("set Gravity = 0, 0\n", elastic("10"), "", "")
        << '\n';
    out << "the same (0.467), first-order scheme: "
        << velocity_interpolation("",
                                  elastic("10"),
                                  "  set Scheme = first order\n",
                                  "")
        << '\n';
    out << "the same (0.467), strain bound local (band in one change): "
        << velocity_interpolation("",
                                  elastic("10"),
                                  "  set Strain bound = local\n",
                                  "")
        << '\n';
    out << "the same (0.467), dumbbells: "
        << velocity_interpolation("",
                                  elastic("10") +
                                    "  set Stress model = dumbbells\n",
                                  "",
                                  "")
        << '\n';
    out << "velocity interpolation automatic, Oldroyd-B liquid: "
        << velocity_interpolation("",
                                  "  set Polymer viscosity = 10\n"
                                  "  set Relaxation time = 0.005\n",
                                  "",
                                  "")
        << '\n';
    out << "velocity interpolation automatic, Newtonian liquid: "
        << velocity_interpolation("", "", "", "") << '\n';
    out << "velocity interpolation linear, elastic solid (0.467): "
        << velocity_interpolation("",
                                  elastic("10"),
                                  "",
                                  "  set Velocity interpolation = linear\n")
        << '\n';
    out << "pressure stabilization 0.25, elastic solid (0.467): "
        << velocity_interpolation(
             "subsection Solver\n  set Pressure stabilization = 0.25\nend\n",
             elastic("10"),
             "",
             "")
        << '\n';
    out << "velocity interpolation cubic, Newtonian liquid: "
        << velocity_interpolation("",
                                  "",
                                  "",
                                  "  set Velocity interpolation = cubic\n")
        << '\n';
  }

  {
    // 'Level set interpolation = automatic': gradient augmented in 2D and
    // for a prescribed velocity, linear for a 3D flow and with 'Band
    // placement = predicted, one change'. Explicit values stay.
    const auto level_set = [](const unsigned int dimension,
                              const std::string &transport,
                              const std::string &mesh,
                              const std::string &extra = "") {
      const std::string cavity_3d =
        "set Gravity = 0, 0, 0\nsubsection Cavity\n"
        "  set Lower corner = 0, 0, 0\n  set Upper corner = 1, 1, 1\n"
        "  set Coarse subdivisions = 1, 1, 1\nend\n"
        "subsection Initial liquid\n  set Shape = ball\n"
        "  set Ball center = 0.5, 0.5, 0.5\n  set Velocity = 0; 0; 0\nend\n";
      write("level_set.prm",
            "set Dimension = " + std::to_string(dimension) + "\n" +
              (dimension == 3 ? cavity_3d : "") + "subsection Transport\n" +
              transport + "end\nsubsection Mesh refinement\n" + mesh + "end\n" +
              extra);
      vefs::Parameters parameters;
      read_and_check(parameters, "level_set.prm");
      switch (parameters.transport.level_set_interpolation)
        {
          case vefs::LevelSetInterpolation::linear:
            return "linear";
          case vefs::LevelSetInterpolation::gradient_augmented:
            return "gradient augmented";
          default:
            return "other";
        }
    };
    out << "level set interpolation automatic, 2D flow: "
        << level_set(2, "", "") << '\n';
    out << "the same, 3D flow: " << level_set(3, "", "") << '\n';
    out << "the same, 3D, prescribed velocity: "
        << level_set(3, "  set Prescribed velocity = 1; 0; 0\n", "") << '\n';
    out << "the same, 2D, band predicted, one change: "
        << level_set(2, "", "  set Band placement = predicted, one change\n")
        << '\n';
    // The seed's soft solid (weight strain 46.7: linear velocity).
    const std::string fixed_steps =
      "subsection Time\n  set Strain bound = local\nend\n"
      "subsection Material\n  set Alpha = 0\n  set Polymer viscosity = 0.1\n"
      "  set Relaxation time = 0.005\nend\n";
    out << "the same, 3D flow, the seed's fixed steps: "
        << level_set(3, "", "", fixed_steps) << '\n';
    out << "the same, 2D flow, the seed's fixed steps: "
        << level_set(2, "", "", fixed_steps) << '\n';
    out << "the same, 3D, prescribed velocity, fixed steps: "
        << level_set(3,
                     "  set Prescribed velocity = 1; 0; 0\n",
                     "",
                     fixed_steps)
        << '\n';
    out << "linear, 2D flow: "
        << level_set(2, "  set Level set interpolation = linear\n", "") << '\n';
  }

  {
    // 'Remap distance = automatic': 20 in 2D and 14 in 3D for the gradient
    // augmented level set carried by a prescribed velocity, unless the band
    // is predicted; 0 otherwise. Redistancing keeps the level set within
    // twice the remap distance in 2D, nowhere in 3D. 'Band width' and 'Band
    // miss tolerance' = automatic: 2 and 0.001 with 'predicted, one change',
    // 2 and 0 with 'predicted', 4 and 0 with 'widened'. Explicit values
    // stay.
    const auto resolved = [](const std::string &transport,
                             const std::string &mesh,
                             const bool         three_d = false) {
      const std::string cavity_3d =
        "set Dimension = 3\nset Gravity = 0, 0, 0\nsubsection Cavity\n"
        "  set Lower corner = 0, 0, 0\n  set Upper corner = 1, 1, 1\n"
        "  set Coarse subdivisions = 1, 1, 1\nend\n"
        "subsection Initial liquid\n  set Shape = ball\n"
        "  set Ball center = 0.5, 0.5, 0.5\n  set Velocity = 0; 0; 0\nend\n";
      write("remap.prm",
            (three_d ? cavity_3d : "set Dimension = 2\n") +
              "subsection Transport\n" + transport +
              "end\nsubsection Mesh refinement\n" + mesh + "end\n");
      vefs::Parameters parameters;
      read_and_check(parameters, "remap.prm");
      std::ostringstream text;
      text << "remap distance " << parameters.transport.remap_distance
           << ", kept at redistancing "
           << parameters.transport.kept_at_redistancing(parameters.dimension)
           << ", band width " << parameters.mesh.band_width
           << ", miss tolerance " << parameters.mesh.band_miss_tolerance;
      return text.str();
    };
    const std::string gradient_augmented =
      "  set Level set interpolation = gradient augmented\n";
    const std::string prescribed = "  set Prescribed velocity = 1; 0\n";
    const std::string linear     = "  set Level set interpolation = linear\n";
    out << "automatic, flow, linear: " << resolved(linear, "") << '\n';
    out << "automatic, flow, gradient augmented: "
        << resolved(gradient_augmented, "") << '\n';
    out << "automatic, prescribed velocity, linear: "
        << resolved(prescribed + linear, "") << '\n';
    out << "automatic, prescribed velocity, gradient augmented: "
        << resolved(prescribed + gradient_augmented, "") << '\n';
    out << "the same, 3D: "
        << resolved("  set Prescribed velocity = 1; 0; 0\n" +
                      gradient_augmented,
                    "",
                    true)
        << '\n';
    out << "the same, band predicted: "
        << resolved(prescribed + gradient_augmented,
                    "  set Band placement = predicted\n")
        << '\n';
    out << "automatic, band predicted, one change: "
        << resolved("", "  set Band placement = predicted, one change\n")
        << '\n';
    out << "explicit values: "
        << resolved(prescribed + gradient_augmented +
                      "  set Remap distance = 3\n",
                    "  set Band width = 5\n")
        << '\n';
    out << "explicit values, one change: "
        << resolved("",
                    "  set Band placement = predicted, one change\n"
                    "  set Band width = 3\n"
                    "  set Band miss tolerance = 0.01\n")
        << '\n';
    for (const std::string &entry :
         {std::string("  set Band miss tolerance = 2\n"),
          std::string("  set Band width = 0.5\n")})
      try
        {
          resolved("",
                   "  set Band placement = predicted, one change\n" + entry);
          out << entry.substr(6, entry.size() - 7) << ": NOT refused\n";
        }
      catch (const vefs::InputError &error)
        {
          out << entry.substr(6, entry.size() - 7) << ": " << error.what()
              << '\n';
        }
  }

  {
    // 'Band placement = automatic': 'predicted, one change' for an elastic
    // solid whose steps 'Strain bound = local' keeps fixed, without a
    // target CFL, with linear interpolation at the feet and no remap;
    // 'widened' otherwise. Explicit values stay.
    const auto placement = [](const std::string &time,
                              const std::string &transport,
                              const std::string &mesh) {
      write("band.prm",
            "set Dimension = 2\nsubsection Material\n"
            "  set Polymer viscosity = 0.1\n  set Relaxation time = 0.005\n"
            "  set Alpha = 0\nend\n"
            "subsection Time\n" +
              time + "end\nsubsection Transport\n" + transport +
              "end\nsubsection Mesh refinement\n" + mesh + "end\n");
      vefs::Parameters parameters;
      read_and_check(parameters, "band.prm");
      return std::string(!parameters.mesh.band_predicted() ? "widened"
                         : parameters.mesh.band_in_one_change()
                           ? "predicted, one change"
                           : "predicted");
    };
    const std::string local  = "  set Strain bound = local\n";
    const std::string linear = "  set Level set interpolation = linear\n";
    out << "band placement automatic, strain bound step: "
        << placement("", linear, "") << '\n';
    out << "band placement automatic, strain bound local: "
        << placement(local, linear, "") << '\n';
    out << "the same, target CFL 5: "
        << placement(local + "  set Target CFL = 5\n", linear, "") << '\n';
    for (const std::string feet :
         {"Level set interpolation = gradient augmented",
          "Level set interpolation = automatic",
          "Velocity interpolation = limited cubic",
          "Stress interpolation = limited cubic",
          "Remap distance = 3"})
      out << "the same, " << feet << ": "
          << placement(local,
                       feet.find("Level set") == 0
                         ? "  set " + feet + "\n"
                         : linear + "  set " + feet + "\n",
                       "")
          << '\n';
    out << "band placement predicted, strain bound local: "
        << placement(local, linear, "  set Band placement = predicted\n")
        << '\n';
    out << "band placement predicted, one change, strain bound step: "
        << placement("", "", "  set Band placement = predicted, one change\n")
        << '\n';
  }
}
