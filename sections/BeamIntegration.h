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
//   'HingeMidpoint'  one point at the middle of each hinge (lp/2, weight lp)
//   'HingeEndpoint'  one point at each end (weight lp)
// with two Gauss points of section secE on the interior.
// Rules with given points, (rule, tag, N, *secTags, *locs <, *wts>):
//   'UserDefined'    the given locations and weights
//   'FixedLocation'  the given locations, weights integrating 1, x, ..., x^(N-1)
//                    exactly (the Vandermonde system of the manual)
//   'MidDistance'    the given locations, each weighted by the distance between
//                    the midpoints to its neighbours (ends at 0 and 1)
//   'LowOrder'       the given locations and the first Nc <= N weights (Nc from
//                    the count of wts); the other N - Nc weights integrate
//                    1, x, ..., x^(N-Nc-1) exactly with the given ones (Kidarsa,
//                    Scott and Higgins 2008): FixedLocation at Nc = 0,
//                    UserDefined at Nc = N
// and with equally spaced points, (rule, tag, secTag, N) or (rule, tag, N, *secTags):
//   'Trapezoidal'       both ends, weights 1/(2(N-1)) at the ends, 1/(N-1) inside
//   'CompositeSimpson'  both ends, N odd, Simpson's rule on each pair of intervals
class BeamIntegration {
 public:
  enum class Rule {
    Lobatto, Legendre, Radau, NewtonCotes, HingeRadau, HingeRadauTwo,
    Trapezoidal, CompositeSimpson, UserDefined, FixedLocation, MidDistance,
    HingeMidpoint, HingeEndpoint, LowOrder
  };
  // The plastic hinge rules, built from (secI, lpI, secJ, lpJ, secE).
  static bool isHinge(Rule rule) {
    return rule == Rule::HingeRadau || rule == Rule::HingeRadauTwo || rule == Rule::HingeMidpoint ||
           rule == Rule::HingeEndpoint;
  }
  struct Hinges {
    int sectionI = 0;
    double lengthI = 0.0;
    int sectionJ = 0;
    double lengthJ = 0.0;
    int sectionInterior = 0;
  };

  // A Gauss or Newton-Cotes rule with one section tag per point.
  BeamIntegration(int tag, Rule rule, std::vector<int> sectionTags);
  // A rule with given locations (UserDefined, FixedLocation, MidDistance,
  // LowOrder); `weights` for UserDefined (N) and LowOrder (the first Nc).
  // Throws OpenSeesError for bad input.
  BeamIntegration(int tag, Rule rule, std::vector<int> sectionTags, std::vector<double> locations,
                  std::vector<double> weights);
  // A hinge rule (HingeRadau, HingeRadauTwo, HingeMidpoint, HingeEndpoint).
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
  static void trapezoidal(int n, std::vector<double>& xi, std::vector<double>& weights);
  static void compositeSimpson(int n, std::vector<double>& xi, std::vector<double>& weights);
  // Weights that integrate 1, x, ..., x^(m-1) exactly on [0, 1] at points xi,
  // the first `given.size()` of them given and the other m found.
  static std::vector<double> momentWeights(const std::vector<double>& xi, const std::vector<double>& given = {});
  static bool hasGivenLocations(Rule rule) {
    return rule == Rule::UserDefined || rule == Rule::FixedLocation || rule == Rule::MidDistance ||
           rule == Rule::LowOrder;
  }
  static std::vector<double> midDistanceWeights(const std::vector<double>& xi);

  static const char* ruleName(Rule rule);
  // Smallest and largest number of points a rule accepts.
  static int minPoints(Rule rule);
  static int maxPoints(Rule rule);

 private:
  int tag_;
  Rule rule_;
  std::vector<int> sectionTags_;
  Hinges hinges_;
  std::vector<double> givenXi_, givenWeights_;  // the rules with given locations
};

}  // namespace beamsolid
