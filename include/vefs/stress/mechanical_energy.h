#ifndef vefs_mechanical_energy_h
#define vefs_mechanical_energy_h

#include <vefs/fields/transported_fields.h>
#include <vefs/stress/rheology.h>
#include <vefs/transport/liquid_domain.h>

namespace vefs
{
  /**
   * The energy of the liquid (or solid) as the flow step sees it: over the
   * liquid part of each cell, the kinetic energy rho |u|^2 / 2, the
   * potential energy -rho g.x (zero at the origin) and the elastic energy
   * Rheology::elastic_energy_density(). Their sum is conserved by the
   * equations of a solid without viscosity under gravity and fixed walls;
   * what a step adds or removes is the scheme's (doc/bouncing_ball.md,
   * "Energy budget").
   */
  struct MechanicalEnergy
  {
    double kinetic   = 0;
    double potential = 0;
    double elastic   = 0;

    double
    total() const
    {
      return kinetic + potential + elastic;
    }
  };

  /** Kinetic energy per volume, rho |u|^2 / 2. */
  template <int dim>
  inline double
  kinetic_energy_density(const double density, const Tensor<1, dim> &u)
  {
    return 0.5 * density * u.norm_square();
  }

  /** Potential energy per volume in the gravity @p g, -rho g.x. */
  template <int dim>
  inline double
  potential_energy_density(const double          density,
                           const Tensor<1, dim> &g,
                           const Point<dim>     &x)
  {
    return -(density * g * x);
  }

  /** The energies of @p fields on @p domain, summed over all ranks. */
  template <int dim>
  MechanicalEnergy
  mechanical_energy(const TransportedFields<dim> &fields,
                    const LiquidDomain<dim>      &domain,
                    const MaterialParameters     &material,
                    const Rheology<dim>          &rheology);
} // namespace vefs

#endif
