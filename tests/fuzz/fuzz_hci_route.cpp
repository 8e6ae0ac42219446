// HCI route mapping: any Route payload a server could send is mapped or refused; a mapped route
// goes back to the same bytes when nothing was edited.
#include "Domain.pb.h"
#include "HciRouteMapper.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    com::ugcs::ucs::proto::Route route;
    if (!route.ParseFromArray(data, int(size)))
        return 0;
    const auto imported = sortie::mission::routeFromHci(route);
    if (!imported.ok())
        return 0;
    const auto exported = sortie::mission::routeToHci(imported->route);
    if (exported.SerializeAsString() != route.SerializeAsString()) {
        std::fprintf(stderr, "fuzz_hci_route: the route read differs from the route written\nread:    %s\nwritten: %s\n",
                     route.ShortDebugString().c_str(), exported.ShortDebugString().c_str());
        std::abort();
    }
    return 0;
}
