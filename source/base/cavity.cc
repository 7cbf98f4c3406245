#include <vefs/base/cavity.h>
#include <vefs/base/parameter_entries.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace vefs
{
  using namespace dealii;

  void
  CavityParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Cavity");
    {
      prm.add_parameter("Lower corner",
                        cavity_lower,
                        "Lower corner of the box-shaped cavity (m).",
                        Patterns::List(Patterns::Double(), 2, 3));
      prm.add_parameter("Upper corner",
                        cavity_upper,
                        "Upper corner of the box-shaped cavity (m).",
                        Patterns::List(Patterns::Double(), 2, 3));
      prm.add_parameter("Coarse subdivisions",
                        coarse_subdivisions,
                        "Number of coarse cells per direction; choose them so "
                        "that coarse cells are roughly cubes. Refinement "
                        "levels count from this mesh.",
                        Patterns::List(Patterns::Integer(1), 2, 3));
    }
    prm.leave_subsection();

    prm.enter_subsection("Walls");
    {
      const std::vector<std::pair<std::string, WallType>> types = {
        {"no-slip", WallType::no_slip},
        {"slip", WallType::slip},
        {"open", WallType::open},
        {"velocity", WallType::velocity},
        {"periodic", WallType::periodic},
        {"contact", WallType::contact}};
      for (unsigned int w = 0; w < 6; ++w)
        {
          add_selection(
            prm,
            wall_names[w],
            wall_type[w],
            types,
            "Condition on the cavity wall " + wall_names[w] + " (boundary id " +
              std::to_string(w) +
              "): no-slip (u = 0), slip (u.n = 0, no tangential "
              "stress), open (zero traction), velocity (u given by the "
              "entry '" +
              wall_names[w] +
              " velocity'), periodic (the opposite wall must be "
              "periodic too: the liquid leaving through one wall enters "
              "through the other) or contact (the seed's Signorini-like "
              "wall: the liquid cannot cross it but may leave it, no "
              "tangential stress; the contact force and the contact "
              "length or area go to the statistics). z walls are used in "
              "3D only.");
          prm.add_parameter(wall_names[w] + " velocity",
                            wall_velocity[w],
                            "Velocity imposed on wall " + wall_names[w] +
                              " when its type is 'velocity': one muParser "
                              "expression per component, separated by ';', "
                              "in x, y, (z,) t.",
                            Patterns::Anything());
        }
    }
    prm.leave_subsection();
  }

  void
  CavityParameters::check(const unsigned int dimension) const
  {
    require_point(cavity_lower, dimension, "Cavity/Lower corner");
    require_point(cavity_upper, dimension, "Cavity/Upper corner");
    require(coarse_subdivisions.size() == dimension,
            "Cavity/Coarse subdivisions",
            "needs " + std::to_string(dimension) + " comma-separated integers");
    for (unsigned int d = 0; d < dimension; ++d)
      require(cavity_lower[d] < cavity_upper[d],
              "Cavity/Upper corner",
              "must exceed 'Cavity/Lower corner' in every coordinate");
    for (unsigned int d = 0; d < dimension; ++d)
      require((wall_type[2 * d] == WallType::periodic) ==
                (wall_type[2 * d + 1] == WallType::periodic),
              "Walls/" + wall_names[2 * d + 1],
              "walls " + wall_names[2 * d] + " and " + wall_names[2 * d + 1] +
                " are periodic together or not at all");
    // A 2D scene has no z walls: an entry there cannot mean anything.
    if (dimension == 2)
      for (unsigned int w = 4; w < 6; ++w)
        {
          std::string compact = wall_velocity[w];
          compact.erase(std::remove_if(compact.begin(),
                                       compact.end(),
                                       [](const char c) {
                                         return std::isspace(
                                           static_cast<unsigned char>(c));
                                       }),
                        compact.end());
          require(compact == "0;0",
                  "Walls/" + wall_names[w] + " velocity",
                  "a 2D scene (Dimension = 2) has no z walls; remove the "
                  "entry");
          require(wall_type[w] == CavityParameters().wall_type[w],
                  "Walls/" + wall_names[w],
                  "a 2D scene (Dimension = 2) has no z walls; remove the "
                  "entry");
        }
  }

  double
  CavityParameters::cell_size(const unsigned int dimension,
                              const unsigned int level) const
  {
    double size = std::numeric_limits<double>::max();
    for (unsigned int d = 0; d < dimension; ++d)
      size = std::min(size,
                      (cavity_upper[d] - cavity_lower[d]) /
                        coarse_subdivisions[d] / (1u << level));
    return size;
  }

  template <int dim>
  bool
  CavityParameters::on_slip_or_contact_wall(const dealii::Point<dim> &p) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double tolerance = 1e-10 * (cavity_upper[d] - cavity_lower[d]);
        for (unsigned int side = 0; side < 2; ++side)
          {
            const WallType type = wall_type[2 * d + side];
            const double   wall = side == 0 ? cavity_lower[d] : cavity_upper[d];
            if ((type == WallType::slip || type == WallType::contact) &&
                std::abs(p[d] - wall) <= tolerance)
              return true;
          }
      }
    return false;
  }

  template bool
  CavityParameters::on_slip_or_contact_wall(const dealii::Point<2> &) const;
  template bool
  CavityParameters::on_slip_or_contact_wall(const dealii::Point<3> &) const;

  bool
  CavityParameters::has_contact_walls(const unsigned int dimension) const
  {
    return std::find(wall_type.begin(),
                     wall_type.begin() + 2 * dimension,
                     WallType::contact) != wall_type.begin() + 2 * dimension;
  }

  std::vector<unsigned int>
  CavityParameters::periodic_directions() const
  {
    std::vector<unsigned int> directions;
    for (unsigned int d = 0; d < 3; ++d)
      if (wall_type[2 * d] == WallType::periodic)
        directions.push_back(d);
    return directions;
  }
} // namespace vefs
