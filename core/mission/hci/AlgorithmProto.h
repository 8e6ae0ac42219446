#pragma once

#include "AlgorithmCatalog.h"

namespace com::ugcs::ucs::proto {
class TraverseAlgorithm;
class ParameterDefinition;
class Selection;
}

namespace sortie::mission {

// Between the server's TraverseAlgorithm objects and AlgorithmDefinition. The wire has no range,
// choices or unit beyond PhysicalSemantic, so reading fills those in from `known` (normally
// AlgorithmCatalog::builtIn()) for parameters it has by the same name; everything the server says
// (type, default, mandatory, category, regex, description) wins. An algorithm or parameter `known`
// lacks is taken as the server describes it, so a newer server's tool still gets an editor.
AlgorithmDefinition algorithmFromProto(const com::ugcs::ucs::proto::TraverseAlgorithm &algorithm,
                                       const AlgorithmCatalog *known = nullptr);
ParameterDefinition parameterFromProto(const com::ugcs::ucs::proto::ParameterDefinition &parameter,
                                       const ParameterDefinition *known = nullptr);
// The description a server sends. Ranges travel in the description text ("1–90 %"), as the wire
// has no field for them.
com::ugcs::ucs::proto::TraverseAlgorithm algorithmToProto(const AlgorithmDefinition &algorithm);

// A catalog of what a server listed, completed from `known`; algorithms only `known` has are kept
// after the server's, so a server that lists fewer tools still opens every segment.
AlgorithmCatalog catalogFromProto(const std::vector<com::ugcs::ucs::proto::TraverseAlgorithm> &algorithms,
                                  const AlgorithmCatalog &known = AlgorithmCatalog::builtIn());

// Puts a server's GetParametersSelectionValues answer into the definition: each selection (by
// selectionId = parameter name) becomes that parameter's choices, its marked item the default when the
// parameter has none. Selections for parameters the definition lacks are ignored.
void applySelections(AlgorithmDefinition &algorithm, const std::vector<com::ugcs::ucs::proto::Selection> &selections);

} // namespace sortie::mission
