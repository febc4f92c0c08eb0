#include "sections/BeamIntegration.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "sections/SectionForceDeformation.h"

namespace beamsolid {

namespace {

// Legendre polynomials P_n(x) and P_{n-1}(x) by the three-term recurrence.
void legendre(int n, double x, double& pn, double& pnMinus1) {
  double p0 = 1.0, p1 = x;
  if (n == 0) {
    pn = 1.0;
    pnMinus1 = 0.0;
    return;
  }
  for (int k = 2; k <= n; ++k) {
    const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  pn = p1;
  pnMinus1 = p0;
}

// Zeros of the degree-m Jacobi polynomial for the weight (1-x)^alpha (1+x)^beta
// on [-1, 1]: eigenvalues of its Jacobi matrix (Golub and Welsch, 1969).
std::vector<double> jacobiZeros(int m, double alpha, double beta) {
  if (m <= 0) return {};
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, m);
  const double ab = alpha + beta;
  for (int n = 0; n < m; ++n) {
    const double s = 2.0 * n + ab;
    J(n, n) = (n == 0 && ab == 0.0) ? (beta - alpha) / (ab + 2.0) : (beta * beta - alpha * alpha) / (s * (s + 2.0));
    if (n >= 1) {
      const double b = std::sqrt(4.0 * n * (n + alpha) * (n + beta) * (n + ab) / (s * s * (s + 1.0) * (s - 1.0)));
      J(n, n - 1) = J(n - 1, n) = b;
    }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(J, Eigen::EigenvaluesOnly);
  std::vector<double> x(eigen.eigenvalues().data(), eigen.eigenvalues().data() + m);
  std::sort(x.begin(), x.end());
  return x;
}

// From [-1, 1] (weights summing to 2) to [0, 1] (summing to 1).
void toUnitInterval(std::vector<double>& xi, std::vector<double>& weights) {
  for (double& x : xi) x = 0.5 * (x + 1.0);
  for (double& w : weights) w *= 0.5;
}

}  // namespace

void BeamIntegration::gaussLegendre(int n, std::vector<double>& xi, std::vector<double>& weights) {
  xi = jacobiZeros(n, 0.0, 0.0);
  weights.resize(n);
  for (int i = 0; i < n; ++i) {
    double pn, pm;
    legendre(n, xi[i], pn, pm);
    const double x = xi[i];
    const double derivative = n * (x * pn - pm) / (x * x - 1.0);
    weights[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
  toUnitInterval(xi, weights);
}

void BeamIntegration::gaussLobatto(int n, std::vector<double>& xi, std::vector<double>& weights) {
  // Interior points: zeros of P'_{n-1}, i.e. of the Jacobi(1, 1) polynomial.
  xi = jacobiZeros(n - 2, 1.0, 1.0);
  xi.insert(xi.begin(), -1.0);
  xi.push_back(1.0);
  weights.resize(n);
  for (int i = 0; i < n; ++i) {
    double pn, pm;
    legendre(n - 1, xi[i], pn, pm);
    weights[i] = 2.0 / (n * (n - 1) * pn * pn);
  }
  toUnitInterval(xi, weights);
}

void BeamIntegration::gaussRadau(int n, std::vector<double>& xi, std::vector<double>& weights) {
  // The fixed point at -1 (end I); the others are zeros of the Jacobi(0, 1) polynomial.
  xi = jacobiZeros(n - 1, 0.0, 1.0);
  xi.insert(xi.begin(), -1.0);
  weights.resize(n);
  weights[0] = 2.0 / (double(n) * n);
  for (int i = 1; i < n; ++i) {
    double pn, pm;
    legendre(n - 1, xi[i], pn, pm);
    weights[i] = (1.0 - xi[i]) / (double(n) * n * pn * pn);
  }
  toUnitInterval(xi, weights);
}

void BeamIntegration::newtonCotes(int n, std::vector<double>& xi, std::vector<double>& weights) {
  xi.resize(n);
  for (int i = 0; i < n; ++i) xi[i] = double(i) / (n - 1);
  weights = momentWeights(xi);
}

std::vector<double> BeamIntegration::momentWeights(const std::vector<double>& xi, const std::vector<double>& given) {
  const int n = static_cast<int>(xi.size());
  const int nc = static_cast<int>(given.size());
  const int m = n - nc;
  if (m == 0) return given;
  // The free weights integrate 1, x, ..., x^(m-1) exactly on [0, 1] together
  // with the given ones (the method of undetermined coefficients).
  Eigen::MatrixXd V(m, m);
  Eigen::VectorXd moments(m);
  for (int k = 0; k < m; ++k) {
    for (int i = 0; i < m; ++i) V(k, i) = std::pow(xi[nc + i], k);
    moments[k] = 1.0 / (k + 1);
    for (int i = 0; i < nc; ++i) moments[k] -= std::pow(xi[i], k) * given[i];
  }
  const Eigen::VectorXd free = V.colPivHouseholderQr().solve(moments);
  std::vector<double> w(given);
  w.insert(w.end(), free.data(), free.data() + m);
  return w;
}

std::vector<double> BeamIntegration::midDistanceWeights(const std::vector<double>& xi) {
  // Each point owns the stretch between the midpoints to its neighbours, the
  // first from 0 and the last to 1 (in the order of the locations).
  const std::size_t n = xi.size();
  std::vector<double> w(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double left = i == 0 ? 0.0 : 0.5 * (xi[i - 1] + xi[i]);
    const double right = i + 1 == n ? 1.0 : 0.5 * (xi[i] + xi[i + 1]);
    w[i] = right - left;
  }
  return w;
}

void BeamIntegration::trapezoidal(int n, std::vector<double>& xi, std::vector<double>& weights) {
  xi.resize(n);
  weights.assign(n, 1.0 / (n - 1));
  for (int i = 0; i < n; ++i) xi[i] = double(i) / (n - 1);
  weights.front() = weights.back() = 0.5 / (n - 1);
}

void BeamIntegration::compositeSimpson(int n, std::vector<double>& xi, std::vector<double>& weights) {
  // Simpson (h/3)(1, 4, 1) on each pair of the n - 1 equal intervals.
  xi.resize(n);
  weights.resize(n);
  const double h = 1.0 / (n - 1);
  for (int i = 0; i < n; ++i) {
    xi[i] = i * h;
    weights[i] = (i == 0 || i == n - 1) ? h / 3.0 : (i % 2 == 1 ? 4.0 * h / 3.0 : 2.0 * h / 3.0);
  }
}

const char* BeamIntegration::ruleName(Rule rule) {
  switch (rule) {
    case Rule::Lobatto: return "Lobatto";
    case Rule::Legendre: return "Legendre";
    case Rule::Radau: return "Radau";
    case Rule::NewtonCotes: return "NewtonCotes";
    case Rule::HingeRadau: return "HingeRadau";
    case Rule::HingeRadauTwo: return "HingeRadauTwo";
    case Rule::Trapezoidal: return "Trapezoidal";
    case Rule::CompositeSimpson: return "CompositeSimpson";
    case Rule::UserDefined: return "UserDefined";
    case Rule::FixedLocation: return "FixedLocation";
    case Rule::MidDistance: return "MidDistance";
    case Rule::HingeMidpoint: return "HingeMidpoint";
    case Rule::HingeEndpoint: return "HingeEndpoint";
    case Rule::LowOrder: return "LowOrder";
  }
  return "?";
}

int BeamIntegration::minPoints(Rule rule) {
  switch (rule) {
    case Rule::Lobatto:
    case Rule::NewtonCotes:
    case Rule::Trapezoidal: return 2;
    case Rule::CompositeSimpson: return 3;
    case Rule::HingeRadau:
    case Rule::HingeRadauTwo: return 6;
    case Rule::HingeMidpoint:
    case Rule::HingeEndpoint: return 4;
    default: return 1;
  }
}

int BeamIntegration::maxPoints(Rule rule) {
  switch (rule) {
    // Closed Newton-Cotes weights turn negative and grow beyond this.
    case Rule::NewtonCotes: return 12;
    case Rule::HingeRadau:
    case Rule::HingeRadauTwo: return 6;
    case Rule::HingeMidpoint:
    case Rule::HingeEndpoint: return 4;
    // FixedLocation's Vandermonde system is ill-conditioned beyond this.
    case Rule::FixedLocation:
    case Rule::LowOrder: return 12;
    default: return 30;
  }
}

BeamIntegration::BeamIntegration(int tag, Rule rule, std::vector<int> sectionTags)
    : tag_(tag), rule_(rule), sectionTags_(std::move(sectionTags)) {
  const int n = numPoints();
  if (isHinge(rule))
    throw OpenSeesError(std::string("beamIntegration ") + ruleName(rule) + " " + std::to_string(tag) +
                        ": a hinge rule needs secI, lpI, secJ, lpJ, secE");
  if (hasGivenLocations(rule))
    throw OpenSeesError(std::string("beamIntegration ") + ruleName(rule) + " " + std::to_string(tag) +
                        ": needs the locations of its points");
  if (n < minPoints(rule) || n > maxPoints(rule))
    throw OpenSeesError(std::string("beamIntegration ") + ruleName(rule) + " " + std::to_string(tag) +
                        ": the number of points must lie in " + std::to_string(minPoints(rule)) + ".." +
                        std::to_string(maxPoints(rule)) + ", got " + std::to_string(n));
  if (rule == Rule::CompositeSimpson && n % 2 == 0)
    throw OpenSeesError(std::string("beamIntegration CompositeSimpson ") + std::to_string(tag) +
                        ": the number of points must be odd, got " + std::to_string(n));
}

BeamIntegration::BeamIntegration(int tag, Rule rule, std::vector<int> sectionTags, std::vector<double> locations,
                                 std::vector<double> weights)
    : tag_(tag), rule_(rule), sectionTags_(std::move(sectionTags)), givenXi_(std::move(locations)) {
  const std::string context = std::string("beamIntegration ") + ruleName(rule) + " " + std::to_string(tag);
  const std::size_t n = sectionTags_.size();
  if (!hasGivenLocations(rule))
    throw OpenSeesError(context + ": not a rule with given locations");
  if (n < 1 || static_cast<int>(n) > maxPoints(rule))
    throw OpenSeesError(context + ": the number of points must lie in 1.." + std::to_string(maxPoints(rule)));
  if (givenXi_.size() != n) throw OpenSeesError(context + ": needs one location per section");
  for (double x : givenXi_)
    if (!(x >= 0.0 && x <= 1.0))
      throw OpenSeesError(context + ": locs must lie in [0, 1] (fractions of the length), got " + std::to_string(x));
  if (rule == Rule::UserDefined) {
    if (weights.size() != n) throw OpenSeesError(context + ": needs one weight per section");
    for (double w : weights)
      if (!std::isfinite(w)) throw OpenSeesError(context + ": wts must be finite numbers");
    givenWeights_ = std::move(weights);
  } else if (rule == Rule::FixedLocation || rule == Rule::LowOrder) {
    if (weights.size() > n) throw OpenSeesError(context + ": at most one weight per section");
    for (double w : weights)
      if (!std::isfinite(w)) throw OpenSeesError(context + ": wts must be finite numbers");
    // Only the points with free weights must be distinct.
    for (std::size_t i = weights.size(); i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (givenXi_[i] == givenXi_[j])
          throw OpenSeesError(context + ": two points without a given weight at the same location " +
                              std::to_string(givenXi_[i]) + " (their weights are undetermined)");
    givenWeights_ = momentWeights(givenXi_, weights);
  } else {
    for (std::size_t i = 1; i < n; ++i)
      if (givenXi_[i] < givenXi_[i - 1])
        throw OpenSeesError(context + ": locs must be in ascending order (the weights come from the midpoints between neighbours)");
    givenWeights_ = midDistanceWeights(givenXi_);
  }
}

BeamIntegration::BeamIntegration(int tag, Rule rule, const Hinges& hinges) : tag_(tag), rule_(rule), hinges_(hinges) {
  if (!isHinge(rule))
    throw OpenSeesError(std::string("beamIntegration ") + ruleName(rule) + " " + std::to_string(tag) +
                        ": not a hinge rule");
  // HingeRadau (Scott and Fenves 2006, modified Radau over 4 lp): only the
  // end points carry the hinge sections; the points at 8/3 lp belong to the
  // interior, so the hinge is lp long (checked against OpenSeesPy).
  // HingeRadauTwo: both points of each hinge region are hinge sections.
  if (rule == Rule::HingeRadau)
    sectionTags_ = {hinges.sectionI, hinges.sectionInterior, hinges.sectionInterior,
                    hinges.sectionInterior, hinges.sectionInterior, hinges.sectionJ};
  else if (rule == Rule::HingeMidpoint || rule == Rule::HingeEndpoint)
    sectionTags_ = {hinges.sectionI, hinges.sectionInterior, hinges.sectionInterior, hinges.sectionJ};
  else
    sectionTags_ = {hinges.sectionI, hinges.sectionI, hinges.sectionInterior,
                    hinges.sectionInterior, hinges.sectionJ, hinges.sectionJ};
}

void BeamIntegration::pointsAndWeights(double length, std::vector<double>& xi, std::vector<double>& weights) const {
  const int n = numPoints();
  switch (rule_) {
    case Rule::Lobatto: gaussLobatto(n, xi, weights); return;
    case Rule::Legendre: gaussLegendre(n, xi, weights); return;
    case Rule::Radau: gaussRadau(n, xi, weights); return;
    case Rule::NewtonCotes: newtonCotes(n, xi, weights); return;
    case Rule::Trapezoidal: trapezoidal(n, xi, weights); return;
    case Rule::CompositeSimpson: compositeSimpson(n, xi, weights); return;
    case Rule::UserDefined:
    case Rule::FixedLocation:
    case Rule::MidDistance:
    case Rule::LowOrder:
      xi = givenXi_;
      weights = givenWeights_;
      return;
    case Rule::HingeRadau:
    case Rule::HingeRadauTwo:
    case Rule::HingeMidpoint:
    case Rule::HingeEndpoint: break;
  }
  // Hinge regions of length span*lp at each end: two-point Radau in each
  // (end point weight 1/4, interior point at 2/3 with weight 3/4 of the span)
  // or one point (the middle or the end) weighted lp.
  const bool onePoint = rule_ == Rule::HingeMidpoint || rule_ == Rule::HingeEndpoint;
  const double span = rule_ == Rule::HingeRadau ? 4.0 : 1.0;
  const double a = span * hinges_.lengthI / length;
  const double b = span * hinges_.lengthJ / length;
  if (a + b > 1.0 + 1e-12)
    throw OpenSeesError(std::string("beamIntegration ") + ruleName(rule_) + " " + std::to_string(tag_) +
                        ": the hinge regions (" + std::to_string(span) + " lpI + " + std::to_string(span) +
                        " lpJ = " + std::to_string((a + b) * length) + ") are longer than the element (" +
                        std::to_string(length) + ")");
  const double interior = std::max(0.0, 1.0 - a - b);
  const double gauss = 0.5 / std::sqrt(3.0);
  if (onePoint) {
    const bool middle = rule_ == Rule::HingeMidpoint;
    xi = {middle ? 0.5 * a : 0.0, a + (0.5 - gauss) * interior, a + (0.5 + gauss) * interior,
          middle ? 1.0 - 0.5 * b : 1.0};
    weights = {a, 0.5 * interior, 0.5 * interior, b};
    return;
  }
  xi = {0.0, 2.0 / 3.0 * a, a + (0.5 - gauss) * interior, a + (0.5 + gauss) * interior, 1.0 - 2.0 / 3.0 * b, 1.0};
  weights = {0.25 * a, 0.75 * a, 0.5 * interior, 0.5 * interior, 0.75 * b, 0.25 * b};
}

namespace {

std::unique_ptr<BeamIntegration> buildRule(CommandArgs& args, Domain& domain, BeamIntegration::Rule rule) {
  const char* name = BeamIntegration::ruleName(rule);
  const int tag = args.nextInt("tag");
  args.setContext(std::string("beamIntegration ") + name + " " + std::to_string(tag));
  if (BeamIntegration::isHinge(rule)) {
    BeamIntegration::Hinges h;
    h.sectionI = args.nextInt("secI");
    std::size_t at = args.position();
    h.lengthI = args.nextDouble("lpI");
    if (!(h.lengthI >= 0.0)) args.failAt(at, "lpI", "a hinge length >= 0");
    h.sectionJ = args.nextInt("secJ");
    at = args.position();
    h.lengthJ = args.nextDouble("lpJ");
    if (!(h.lengthJ >= 0.0)) args.failAt(at, "lpJ", "a hinge length >= 0");
    h.sectionInterior = args.nextInt("secE");
    args.expectEnd();
    for (int s : {h.sectionI, h.sectionJ, h.sectionInterior}) domain.sections.get(s, args.context());
    return std::make_unique<BeamIntegration>(tag, rule, h);
  }
  if (BeamIntegration::hasGivenLocations(rule)) {
    const std::size_t at = args.position();
    const int n = args.nextInt("N");
    if (n < 1 || n > BeamIntegration::maxPoints(rule))
      args.failAt(at, "N", "a number of points in 1.." + std::to_string(BeamIntegration::maxPoints(rule)));
    const bool withWeights = rule == BeamIntegration::Rule::UserDefined;
    const bool someWeights = rule == BeamIntegration::Rule::LowOrder;
    const std::size_t expected = static_cast<std::size_t>(n) * (withWeights ? 3 : 2);
    const std::size_t got = args.remaining();
    if (someWeights ? (got < expected || got > expected + n) : got != expected)
      args.fail(std::string("expected N, *secTags, *locs") + (withWeights ? ", *wts" : someWeights ? ", *wts (0 to N of them)" : "") +
                ": " + (someWeights ? std::to_string(expected) + " to " + std::to_string(expected + n) : std::to_string(expected)) +
                " numbers after N = " + std::to_string(n) + ", got " + std::to_string(got));
    std::vector<int> sectionTags;
    std::vector<double> locs, wts;
    for (int i = 0; i < n; ++i) sectionTags.push_back(args.nextInt("secTag"));
    for (int i = 0; i < n; ++i) {
      const std::size_t li = args.position();
      locs.push_back(args.nextDouble("loc"));
      if (!(locs.back() >= 0.0 && locs.back() <= 1.0)) args.failAt(li, "loc", "a location in [0, 1]");
    }
    while (!args.done()) wts.push_back(args.nextDouble("wt"));
    args.expectEnd();
    for (int s : sectionTags) domain.sections.get(s, args.context());
    return std::make_unique<BeamIntegration>(tag, rule, std::move(sectionTags), std::move(locs), std::move(wts));
  }
  const std::size_t numbers = args.remaining();
  std::vector<int> sectionTags;
  if (numbers == 2) {
    const int secTag = args.nextInt("secTag");
    const std::size_t at = args.position();
    const int n = args.nextInt("N");
    if (n < BeamIntegration::minPoints(rule) || n > BeamIntegration::maxPoints(rule))
      args.failAt(at, "N", "a number of points in " + std::to_string(BeamIntegration::minPoints(rule)) + ".." +
                              std::to_string(BeamIntegration::maxPoints(rule)));
    sectionTags.assign(n, secTag);
  } else if (numbers > 2) {
    const std::size_t at = args.position();
    const int n = args.nextInt("N");
    if (n < BeamIntegration::minPoints(rule) || n > BeamIntegration::maxPoints(rule))
      args.failAt(at, "N", "a number of points in " + std::to_string(BeamIntegration::minPoints(rule)) + ".." +
                              std::to_string(BeamIntegration::maxPoints(rule)));
    if (static_cast<int>(args.remaining()) != n)
      args.fail("the non-prismatic form (N, *secTags) needs " + std::to_string(n) + " section tags, got " +
                std::to_string(args.remaining()));
    for (int i = 0; i < n; ++i) sectionTags.push_back(args.nextInt("secTag"));
  } else {
    args.fail("expected secTag, N (or N, *secTags) after the tag");
  }
  args.expectEnd();
  for (int s : sectionTags) domain.sections.get(s, args.context());
  return std::make_unique<BeamIntegration>(tag, rule, std::move(sectionTags));
}

void registerBeamIntegrations(Registry& r) {
  using Rule = BeamIntegration::Rule;
  for (Rule rule : {Rule::Lobatto, Rule::Legendre, Rule::Radau, Rule::NewtonCotes, Rule::HingeRadau,
                    Rule::HingeRadauTwo, Rule::Trapezoidal, Rule::CompositeSimpson, Rule::UserDefined,
                    Rule::FixedLocation, Rule::MidDistance, Rule::HingeMidpoint, Rule::HingeEndpoint, Rule::LowOrder})
    r.beamIntegrations.add(BeamIntegration::ruleName(rule),
                           [rule](CommandArgs& args, Domain& domain) { return buildRule(args, domain, rule); });
}

}  // namespace

BEAMSOLID_REGISTER(registerBeamIntegrations);

}  // namespace beamsolid
