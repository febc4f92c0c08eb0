// Reports of the Interpreter: modalProperties after eigen, printA and printB
// of the last analysis' linear system.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>

#include "analysis/ModalProperties.h"
#include "analysis/ResponseSpectrumAnalysis.h"
#include "bindings/Interpreter.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

using Result = Interpreter::Result;

namespace {

void writeTo(CommandArgs& a, const std::string& file, const std::string& text) {
  if (file.empty()) {
    std::cout << text << std::flush;
    return;
  }
  std::ofstream out(file);
  if (!out) a.fail("cannot open file '" + file + "' for writing");
  out << text;
}

}  // namespace

// modalProperties('-print', '-file', name, '-unorm', '-return')
Result Interpreter::modalProperties(CommandArgs& a) {
  bool print = false, unorm = false, ret = false;
  std::string file;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-print") print = true;
    else if (opt == "-file") file = a.nextString("reportFileName");
    else if (opt == "-unorm") unorm = true;
    else if (opt == "-return") ret = true;
    else a.fail("unknown option '" + opt + "' (expected -print, -file, -unorm or -return)");
  }
  if (eigenvalues_.empty()) a.fail("no eigenvalues: call eigen first");
  ModalProperties properties(*domain_, eigenvalues_, unorm);
  haveModalProperties_ = true;
  if (print || !file.empty()) {
    std::ostringstream text;
    properties.report(text);
    if (print) writeTo(a, "", text.str());
    if (!file.empty()) writeTo(a, file, text.str());
  }
  if (ret) return properties.toDict();
  return {};
}

// responseSpectrumAnalysis(tsTag, dir, <'-scale', s>, <'-mode', m>) or
// responseSpectrumAnalysis(dir, '-Tn', *Tn, '-Sa', *Sa, <'-scale', s>, <'-mode', m>).
// A timeSeries gives Sa(T) as its factor at time T (a Path is zero outside its
// times); the lists are interpolated linearly and held constant past either
// end, as OpenSees. '-scale' is accepted and, as OpenSees documents, unused.
Result Interpreter::responseSpectrumAnalysis(CommandArgs& a) {
  const int first = a.nextInt("tsTag (or direction, with -Tn and -Sa)");
  std::shared_ptr<TimeSeries> series;
  int direction = first;
  if (!a.done() && a.nextIsNumber()) {
    series = domain_->timeSeries.shared(first, "responseSpectrumAnalysis");
    direction = a.nextInt("direction");
  }
  std::vector<double> Tn, Sa;
  int mode = 0;
  bool haveTn = false, haveSa = false;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-scale") a.nextDouble("scale");
    else if (opt == "-mode") mode = a.nextInt("mode");
    else if (opt == "-Tn") { Tn = a.nextDoubles("Tn", 1); haveTn = true; }
    else if (opt == "-Sa") { Sa = a.nextDoubles("Sa", 1); haveSa = true; }
    else a.fail("unknown option '" + opt + "' (expected -scale, -mode, -Tn or -Sa)");
  }
  if (series && (haveTn || haveSa)) a.fail("give either a timeSeries tag or the lists -Tn and -Sa, not both");
  if (!series) {
    if (!haveTn || !haveSa) a.fail("no spectrum: give a timeSeries tag, or the lists '-Tn', *periods, '-Sa', *accelerations");
    if (Tn.size() != Sa.size())
      a.fail("-Tn has " + std::to_string(Tn.size()) + " periods but -Sa " + std::to_string(Sa.size()) + " values");
    for (std::size_t i = 1; i < Tn.size(); ++i)
      if (!(Tn[i] > Tn[i - 1])) a.fail("-Tn must be increasing");
  }
  const int ndm = domain_->spaceDim();
  const int numDirections = ndm == 1 ? 1 : ndm == 2 ? 3 : 6;
  if (direction < 1 || direction > numDirections)
    a.fail("direction " + std::to_string(direction) + " is out of range 1.." + std::to_string(numDirections));
  if (eigenvalues_.empty() || !haveModalProperties_)
    a.fail("eigen and modalProperties have not been called (call eigen(n), then modalProperties())");
  const int numModes = static_cast<int>(eigenvalues_.size());
  if (mode != 0 && (mode < 1 || mode > numModes))
    a.fail("mode " + std::to_string(mode) + " is out of range 1.." + std::to_string(numModes));
  auto spectrum = [&](double T) {
    if (series) return series->factor(T);
    if (T <= Tn.front()) return Sa.front();
    if (T >= Tn.back()) return Sa.back();
    const std::size_t i = std::upper_bound(Tn.begin(), Tn.end(), T) - Tn.begin();
    return Sa[i - 1] + (Sa[i] - Sa[i - 1]) * (T - Tn[i - 1]) / (Tn[i] - Tn[i - 1]);
  };
  ModalProperties properties(*domain_, eigenvalues_, false);
  ResponseSpectrumAnalysis::run(*domain_, properties, direction, spectrum, mode);
  domain_->flushRecorders();
  return {};
}

namespace {

// printA/printB options: '-file', name and '-ret'.
struct PrintOptions {
  std::string file;
  bool ret = false;
};

PrintOptions readPrintOptions(CommandArgs& a) {
  PrintOptions o;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-file") o.file = a.nextString("fileName");
    else if (opt == "-ret") o.ret = true;
    else a.fail("unknown option '" + opt + "' (expected -file or -ret)");
  }
  return o;
}

}  // namespace

// printA: the system matrix as the last iteration formed it, in equation order.
Result Interpreter::printA(CommandArgs& a) {
  const PrintOptions o = readPrintOptions(a);
  if (!analysis_ || analysis_->model().system().size() == 0)
    a.fail("no system matrix: call analysis(...) and analyze(...) first");
  const SparseView s = analysis_->model().system().view();
  const int n = s.n;
  Matrix dense = Matrix::Zero(n, n);
  for (int j = 0; j < n; ++j)
    for (int k = s.colStart[j]; k < s.colStart[j + 1]; ++k) dense(s.rowIndex[k], j) = s.values[k];
  if (o.ret) {
    std::vector<double> rowMajor;
    rowMajor.reserve(static_cast<std::size_t>(n) * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) rowMajor.push_back(dense(i, j));
    return rowMajor;
  }
  std::ostringstream text;
  text << "\n";
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) text << dense(i, j) << " ";
    text << "\n";
  }
  text << "\n";
  writeTo(a, o.file, text.str());
  return {};
}

// printB: the right-hand side (the unbalance after the last iteration).
Result Interpreter::printB(CommandArgs& a) {
  const PrintOptions o = readPrintOptions(a);
  if (!analysis_ || analysis_->model().system().size() == 0)
    a.fail("no right-hand side: call analysis(...) and analyze(...) first");
  const Vector& b = analysis_->model().system().b();
  if (o.ret) return std::vector<double>(b.data(), b.data() + b.size());
  std::ostringstream text;
  for (int i = 0; i < b.size(); ++i) text << b[i] << " ";
  text << "\n";
  writeTo(a, o.file, text.str());
  return {};
}

}  // namespace beamsolid
