#pragma once
#include <string>
#include <vector>

namespace beamsolid {

// beamIntegration(rule, tag, ...): where a beam-column element samples its
// sections and with what weights. Locations are fractions xi of the element
// length, ascending in [0, 1]; the weights sum to 1 (multiply by L).
//   'Lobatto'      N Gauss-Lobatto points, both ends (exact to degree 2N-3)
//   'Legendre'     N Gauss-Legendre points (degree 2N-1)
//   'Radau'        N Gauss-Radau points with one at end I (degree 2N-2)
//   'NewtonCotes'  N equally spaced points, both ends (closed rule)
// each as (rule, tag, secTag, N) or (rule, tag, N, *secTags), and the
// plastic hinge rules of Scott and Fenves (2006) (rule, tag, secI, lpI,
// secJ, lpJ, secE):
//   'HingeRadau'     modified two-point Radau over 4*lp at each end: points at
//                    the end (weight lp, the hinge section) and 8/3 lp inside
//                    (weight 3 lp, section secE): the hinge is lp long
//   'HingeRadauTwo'  two-point Radau over lp: the end (lp/4) and 2/3 lp (3lp/4),
//                    both the hinge section
// with two Gauss points of section secE on the interior.
class BeamIntegration {
 public:
  enum class Rule { Lobatto, Legendre, Radau, NewtonCotes, HingeRadau, HingeRadauTwo };
  struct Hinges {
    int sectionI = 0;
    double lengthI = 0.0;
    int sectionJ = 0;
    double lengthJ = 0.0;
    int sectionInterior = 0;
  };

  // A Gauss or Newton-Cotes rule with one section tag per point.
  BeamIntegration(int tag, Rule rule, std::vector<int> sectionTags);
  // A hinge rule (HingeRadau, HingeRadauTwo).
  BeamIntegration(int tag, Rule rule, const Hinges& hinges);

  int tag() const { return tag_; }
  Rule rule() const { return rule_; }
  std::string className() const { return ruleName(rule_); }
  int numPoints() const { return static_cast<int>(sectionTags_.size()); }
  // The section of each point, in the order of the points.
  const std::vector<int>& sectionTags() const { return sectionTags_; }

  // Locations and weights for an element of this length (hinge rules depend
  // on it); throws OpenSeesError when the hinges do not fit.
  void pointsAndWeights(double length, std::vector<double>& xi, std::vector<double>& weights) const;

  // The rules on [0, 1] with n points.
  static void gaussLobatto(int n, std::vector<double>& xi, std::vector<double>& weights);
  static void gaussLegendre(int n, std::vector<double>& xi, std::vector<double>& weights);
  static void gaussRadau(int n, std::vector<double>& xi, std::vector<double>& weights);
  static void newtonCotes(int n, std::vector<double>& xi, std::vector<double>& weights);

  static const char* ruleName(Rule rule);
  // Smallest and largest number of points a rule accepts.
  static int minPoints(Rule rule);
  static int maxPoints(Rule rule);

 private:
  int tag_;
  Rule rule_;
  std::vector<int> sectionTags_;
  Hinges hinges_;
};

}  // namespace beamsolid
