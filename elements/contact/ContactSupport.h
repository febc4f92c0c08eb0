#pragma once
#include <initializer_list>
#include <string>
#include <vector>

#include "core/Types.h"

namespace beamsolid {

class CommandArgs;
class Node;

// Small pieces shared by the beam contact elements (BeamContact3D/3Dp along
// the shaft, BeamEndContact3D/3Dp at the tip), so that each is written once.

// exp(skew(w)): the rotation by |w| about w, the update of the nodal frames
// (beam_contact_formulation.md, C1).
Matrix3 rotationExp(const Vector3& w);

// Throws "<context>: <role> <tag> has <n> dofs, expected <ndf>".
void requireNodeDofs(const Node& node, int ndf, const char* role, const std::string& context);
// Throws when a tag appears twice: beam, secondary and multiplier nodes must be distinct.
void requireDistinctNodes(const std::vector<int>& tags, const std::string& context);

// Command arguments: the next number, required positive / non-negative
// (errors name the argument), and the optional trailing initial contact
// switch (0: in contact from the start, the default; 1: not).
double readPositive(CommandArgs& args, const char* what);
double readNonNegative(CommandArgs& args, const char* what);
int readContactSwitch(CommandArgs& args, const char* what);

// Responses: names are matched case-insensitively; values print without
// negative zeros.
std::string lowerCase(std::string s);
Vector withoutNegativeZeros(Vector v);
Vector vectorOf(std::initializer_list<double> values);

}  // namespace beamsolid
