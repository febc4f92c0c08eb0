// Reports of the Interpreter: modalProperties after eigen, printA and printB
// of the last analysis' linear system.
#include <fstream>
#include <iostream>
#include <sstream>

#include "analysis/ModalProperties.h"
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
  if (print || !file.empty()) {
    std::ostringstream text;
    properties.report(text);
    if (print) writeTo(a, "", text.str());
    if (!file.empty()) writeTo(a, file, text.str());
  }
  if (ret) return properties.toDict();
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
