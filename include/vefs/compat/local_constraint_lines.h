#ifndef vefs_local_constraint_lines_h
#define vefs_local_constraint_lines_h

#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * The owned lines of closed constraints, with the places on this rank of
   * their constrained entries and of the entries these depend on, worked
   * out once: distribute() then sets the constrained entries as
   * AffineConstraints::distribute() does, summing in the same order,
   * without looking any global index up. The one distribution of the
   * fields' vectors (TransportedFields) and of the flow's block vectors
   * (ConstraintDistribution), which differ in how an entry is found only.
   */
  template <typename Place>
  class LocalConstraintLines
  {
  public:
    /**
     * Keep the lines of @p constraints (closed) whose constrained index
     * @p target_of places (`bool target_of(index, Place &)`: false if this
     * rank does not own it), with their entries placed by @p source_of
     * (the same signature: false if the entry has no place here). Returns
     * whether every entry has a place; if not, the caller must fall back to
     * deal.II's distribute(), on every rank. Not collective.
     */
    template <typename TargetOf, typename SourceOf>
    bool
    reinit(const AffineConstraints<double> &constraints,
           const TargetOf                  &target_of,
           const SourceOf                  &source_of)
    {
      targets.clear();
      inhomogeneities.clear();
      entry_start.assign(1, 0);
      entry_places.clear();
      entry_weights.clear();
      bool  complete = true;
      Place place{};
      for (const auto &line : constraints.get_lines())
        if (target_of(line.index, place))
          {
            targets.push_back(place);
            inhomogeneities.push_back(line.inhomogeneity);
            for (const auto &[index, weight] : line.entries)
              {
                complete = source_of(index, place) && complete;
                entry_places.push_back(place);
                entry_weights.push_back(weight);
              }
            entry_start.push_back(entry_places.size());
          }
      return complete;
    }

    /**
     * Set each constrained entry, `write(place, value)`, from the values
     * `read(place)` of the entries it depends on. Closed constraints: no
     * entry read is written, so one vector may be both.
     */
    template <typename Read, typename Write>
    void
    distribute(const Read &read, const Write &write) const
    {
      for (unsigned int i = 0; i < targets.size(); ++i)
        {
          double value = inhomogeneities[i];
          for (unsigned int e = entry_start[i]; e < entry_start[i + 1]; ++e)
            value += read(entry_places[e]) * entry_weights[e];
          write(targets[i], value);
        }
    }

  private:
    /** Per line: its place, inhomogeneity and entries
     * [entry_start[i], entry_start[i + 1]). */
    std::vector<Place>        targets;
    std::vector<double>       inhomogeneities;
    std::vector<unsigned int> entry_start;
    std::vector<Place>        entry_places;
    std::vector<double>       entry_weights;
  };
} // namespace vefs

#endif
