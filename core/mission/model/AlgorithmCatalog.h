#pragma once

#include "AlgorithmDefinition.h"

#include <vector>

namespace sortie::mission {

// A set of algorithm definitions looked up by class name: the built-in one (every UgCS tool in
// shared/ugcs-route-segments.md, with the wire names, units and defaults found there, and Sortie's
// own names where the facts say "not found", see docs/missions.md), or the one a server described.
class AlgorithmCatalog
{
public:
    AlgorithmCatalog() = default;
    explicit AlgorithmCatalog(std::vector<AlgorithmDefinition> algorithms) : m_algorithms(std::move(algorithms)) {}

    // The definitions Sortie knows without a server. Immutable; built on first use.
    static const AlgorithmCatalog &builtIn();

    const std::vector<AlgorithmDefinition> &algorithms() const { return m_algorithms; }
    const AlgorithmDefinition *byClassName(QStringView className) const;
    const AlgorithmDefinition *byKind(AlgorithmKind kind) const;
    // Adds the definition, replacing one with the same class name.
    void insert(AlgorithmDefinition definition);
    bool operator==(const AlgorithmCatalog &) const = default;

private:
    std::vector<AlgorithmDefinition> m_algorithms;
};

// The kind of a class name (full or short, e.g. "CircleAlgorithm"); Unknown for any other.
AlgorithmKind algorithmKindOf(QStringView className);
// The full class name Sortie uses for a kind ("com.ugcs.ucs.service.routing.impl.CircleAlgorithm").
QString algorithmClassName(AlgorithmKind kind);

} // namespace sortie::mission
