#include "elements/contact/ContactSupport.h"

#include <algorithm>
#include <cctype>

#include "core/CommandArgs.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

Matrix3 rotationExp(const Vector3& w) {
  const double angle = w.norm();
  if (angle == 0.0) return Matrix3::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

void requireNodeDofs(const Node& node, int ndf, const char* role, const std::string& context) {
  if (node.ndf() != ndf)
    throw OpenSeesError(context + ": " + role + " " + std::to_string(node.tag()) + " has " +
                        std::to_string(node.ndf()) + " dofs, expected " + std::to_string(ndf));
}

void requireDistinctNodes(const std::vector<int>& tags, const std::string& context) {
  for (std::size_t i = 0; i < tags.size(); ++i)
    for (std::size_t j = i + 1; j < tags.size(); ++j)
      if (tags[i] == tags[j])
        throw OpenSeesError(context + ": node " + std::to_string(tags[i]) +
                            " appears twice; the beam, secondary and multiplier nodes must be distinct");
}

double readPositive(CommandArgs& args, const char* what) {
  const std::size_t at = args.position();
  const double value = args.nextDouble(what);
  if (!(value > 0.0)) args.failAt(at, what, "a positive number");
  return value;
}

double readNonNegative(CommandArgs& args, const char* what) {
  const std::size_t at = args.position();
  const double value = args.nextDouble(what);
  if (!(value >= 0.0)) args.failAt(at, what, "a number >= 0");
  return value;
}

int readContactSwitch(CommandArgs& args, const char* what) {
  if (args.done()) return 0;
  const std::size_t at = args.position();
  const int value = args.nextInt(what);
  if (value != 0 && value != 1) args.failAt(at, what, "0 (initially in contact) or 1 (initially not in contact)");
  return value;
}

std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

Vector withoutNegativeZeros(Vector v) {
  v.array() += 0.0;  // -0.0 + 0.0 is +0.0
  return v;
}

Vector vectorOf(std::initializer_list<double> values) {
  Vector v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values) v(i++) = x;
  return v;
}

}  // namespace beamsolid
