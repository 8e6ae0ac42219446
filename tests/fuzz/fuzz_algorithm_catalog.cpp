// The tools a server describes (AlgorithmProto.h): a TraverseAlgorithm (its first 16-bit big-endian
// length) and a GetParametersSelectionValuesResponse (the rest) a server could send become a
// catalog that still holds every built-in tool and the server's own, a segment made from it with
// its defaults, and values read and set through it; what Sortie sends back describes the same tool.
#include "AlgorithmProto.h"
#include "Domain.pb.h"
#include "Messages.pb.h"
#include "NewSegmentDefaults.h"
#include "SegmentParameters.h"

#include <cstdio>
#include <cstdlib>

namespace {
[[noreturn]] void fail(const char *why)
{
    std::fprintf(stderr, "fuzz_algorithm_catalog: %s\n", why);
    std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::mission;
    namespace pb = com::ugcs::ucs::proto;
    if (size < 2)
        return 0;
    const size_t length = std::min(size_t(data[0]) << 8 | data[1], size - 2);
    pb::TraverseAlgorithm algorithm;
    pb::GetParametersSelectionValuesResponse selections;
    if (!algorithm.ParseFromArray(data + 2, int(length)) || !selections.ParseFromArray(data + 2 + length, int(size - 2 - length)))
        return 0;

    const AlgorithmCatalog catalog = catalogFromProto({algorithm});
    for (const AlgorithmDefinition &known : AlgorithmCatalog::builtIn().algorithms())
        if (!catalog.byClassName(known.className))
            fail("a built-in tool is missing from the catalog");
    const AlgorithmDefinition *found = catalog.byClassName(QString::fromStdString(algorithm.implementationclass()));
    if (!found)
        fail("the server's tool is missing from the catalog");
    AlgorithmDefinition definition = *found;
    applySelections(definition, {selections.selections().begin(), selections.selections().end()});
    if (definition.minimumPoints < 1)
        fail("a tool that needs no point");

    // What Sortie sends back describes the same tool, parameter by parameter.
    const AlgorithmDefinition back = algorithmFromProto(algorithmToProto(definition), &catalog);
    if (back.className != definition.className || back.parameters.size() != definition.parameters.size())
        fail("the tool sent back is another tool");
    for (size_t i = 0; i < back.parameters.size(); ++i)
        if (back.parameters[i].name != definition.parameters[i].name || back.parameters[i].type != definition.parameters[i].type
            || back.parameters[i].defaultValue != definition.parameters[i].defaultValue)
            fail("a parameter sent back is another parameter");

    // A segment of the tool with its defaults; every value read, and set back to itself.
    AlgorithmCatalog withSelections = catalog;
    withSelections.insert(definition);
    AlgorithmSegment segment;
    segment.algorithm = definition.className;
    segment.figure = definition.figure;
    RouteSettings settings;
    applyToolDefaults(segment, definition, settings);
    Segment s = segment;
    for (const QString &name : parameterNames(s, withSelections)) {
        const QVariant value = parameterValue(s, name, withSelections);
        if (!value.isValid())
            continue;
        QString why;
        Segment copy = s;
        if (!setParameterValue(copy, name, value, &why, withSelections) && why.isEmpty())
            fail("a value refused without a reason");
    }
    return 0;
}
