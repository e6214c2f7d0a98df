#include "EditControl.h"

#include "geoshaping/deform/transfer_function.h"

#include <algorithm>
#include <cmath>

namespace geoshaping::interactor
{

void append_point_dabs(const std::vector<long long>& ids, const std::vector<double>& distances,
  double radius, double value, double strength, Falloff falloff, std::vector<double>& triples)
{
  if (!(radius > 0.0) || ids.size() != distances.size())
  {
    return;
  }
  value = clean_malleability(value);
  strength = std::isfinite(strength) ? std::clamp(strength, 0.0, 1.0) : 0.0;
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    const double w = strength * falloff_weight(falloff, distances[i] / radius);
    if (ids[i] >= 0 && w > 0.0)
    {
      triples.insert(triples.end(), { double(ids[i]), value, w });
    }
  }
}

int redoable_steps(
  int redoable_edits, const std::vector<std::string>& redo_labels, const std::string& stroke_label)
{
  return std::max(redoable_edits, 0) +
         int(std::count(redo_labels.begin(), redo_labels.end(), stroke_label));
}

} // namespace geoshaping::interactor
