#include "HciMessageTypes.h"

#include "Messages.pb.h"

#include <algorithm>
#include <array>
#include <string>
#include <unordered_map>

namespace sortie::hci {
namespace {

namespace pb = com::ugcs::ucs::proto;

struct Entry {
    int32_t number;
    const google::protobuf::Message *prototype;
};

// HCI message type numbers as UgCS 5.x maps them (HciMessageMapping): 204 entries, sorted by number.
// The mapping is a bijection: each number names one message and each message has one number.
const std::array kTable = {
    Entry{0, &pb::Error::default_instance()},
    Entry{1, &pb::Notification::default_instance()},
    Entry{2, &pb::OperationStatus::default_instance()},
    Entry{3, &pb::OperationStream::default_instance()},
    Entry{4, &pb::OperationStreamRequest::default_instance()},
    Entry{5, &pb::CancelOperationRequest::default_instance()},
    Entry{6, &pb::CancelOperationResponse::default_instance()},
    Entry{10, &pb::GetObjectListRequest::default_instance()},
    Entry{11, &pb::GetObjectListResponse::default_instance()},
    Entry{12, &pb::GetObjectRequest::default_instance()},
    Entry{13, &pb::GetObjectResponse::default_instance()},
    Entry{14, &pb::CreateOrUpdateObjectRequest::default_instance()},
    Entry{15, &pb::CreateOrUpdateObjectResponse::default_instance()},
    Entry{16, &pb::DeleteObjectRequest::default_instance()},
    Entry{17, &pb::DeleteObjectResponse::default_instance()},
    Entry{18, &pb::UpdateObjectFieldsRequest::default_instance()},
    Entry{19, &pb::UpdateObjectFieldsResponse::default_instance()},
    Entry{20, &pb::AuthorizeHciRequest::default_instance()},
    Entry{21, &pb::AuthorizeHciResponse::default_instance()},
    Entry{22, &pb::LoginRequest::default_instance()},
    Entry{23, &pb::LoginResponse::default_instance()},
    Entry{24, &pb::LogoutRequest::default_instance()},
    Entry{25, &pb::LogoutResponse::default_instance()},
    Entry{30, &pb::GetRasterGridRequest::default_instance()},
    Entry{31, &pb::GetRasterGridResponse::default_instance()},
    Entry{32, &pb::ProcessRouteRequest::default_instance()},
    Entry{33, &pb::ProcessRouteResponse::default_instance()},
    Entry{34, &pb::GetRasterValuesRequest::default_instance()},
    Entry{35, &pb::GetRasterValuesResponse::default_instance()},
    Entry{36, &pb::GetTelemetryRequest::default_instance()},
    Entry{37, &pb::GetTelemetryResponse::default_instance()},
    Entry{38, &pb::GetKmlRouteRepresentationRequest::default_instance()},
    Entry{39, &pb::GetKmlRouteRepresentationResponse::default_instance()},
    Entry{42, &pb::SetHciLocaleRequest::default_instance()},
    Entry{43, &pb::SetHciLocaleResponse::default_instance()},
    Entry{44, &pb::ConvertRouteAltitudesRequest::default_instance()},
    Entry{45, &pb::ConvertRouteAltitudesResponse::default_instance()},
    Entry{46, &pb::GetLineOfSightRequest::default_instance()},
    Entry{47, &pb::GetLineOfSightResponse::default_instance()},
    Entry{48, &pb::GetElevationProfileRequest::default_instance()},
    Entry{49, &pb::GetElevationProfileResponse::default_instance()},
    Entry{50, &pb::GetAdsbAircraftListRequest::default_instance()},
    Entry{51, &pb::GetAdsbAircraftListResponse::default_instance()},
    Entry{52, &pb::SearchPlacesRequest::default_instance()},
    Entry{53, &pb::SearchPlacesResponse::default_instance()},
    Entry{54, &pb::ExportRouteRequest::default_instance()},
    Entry{55, &pb::ExportRouteResponse::default_instance()},
    Entry{56, &pb::ImportRouteRequest::default_instance()},
    Entry{57, &pb::ImportRouteResponse::default_instance()},
    Entry{58, &pb::SubscribeEventRequest::default_instance()},
    Entry{59, &pb::SubscribeEventResponse::default_instance()},
    Entry{60, &pb::UnsubscribeEventRequest::default_instance()},
    Entry{61, &pb::UnsubscribeEventResponse::default_instance()},
    Entry{62, &pb::GetVehicleLogRequest::default_instance()},
    Entry{63, &pb::GetVehicleLogResponse::default_instance()},
    Entry{64, &pb::SendCommandRequest::default_instance()},
    Entry{65, &pb::SendCommandResponse::default_instance()},
    Entry{66, &pb::UploadRouteRequest::default_instance()},
    Entry{67, &pb::UploadRouteResponse::default_instance()},
    Entry{68, &pb::GetLicenseRequest::default_instance()},
    Entry{69, &pb::GetLicenseResponse::default_instance()},
    Entry{70, &pb::ActivateLicenseRequest::default_instance()},
    Entry{71, &pb::ActivateLicenseResponse::default_instance()},
    Entry{72, &pb::ExportMissionRequest::default_instance()},
    Entry{73, &pb::ExportMissionResponse::default_instance()},
    Entry{74, &pb::ImportMissionRequest::default_instance()},
    Entry{75, &pb::ImportMissionResponse::default_instance()},
    Entry{76, &pb::AcquireLockRequest::default_instance()},
    Entry{77, &pb::AcquireLockResponse::default_instance()},
    Entry{78, &pb::ReleaseLockRequest::default_instance()},
    Entry{79, &pb::ReleaseLockResponse::default_instance()},
    Entry{80, &pb::CheckLockRequest::default_instance()},
    Entry{81, &pb::CheckLockResponse::default_instance()},
    Entry{82, &pb::CheckMultipleLocksRequest::default_instance()},
    Entry{83, &pb::CheckMultipleLocksResponse::default_instance()},
    Entry{84, &pb::GetMissionPreferencesRequest::default_instance()},
    Entry{85, &pb::GetMissionPreferencesResponse::default_instance()},
    Entry{86, &pb::UpdateMissionPreferencesRequest::default_instance()},
    Entry{87, &pb::UpdateMissionPreferencesResponse::default_instance()},
    Entry{88, &pb::GetVehicleLogByTimeRangeRequest::default_instance()},
    Entry{89, &pb::GetVehicleLogByTimeRangeResponse::default_instance()},
    Entry{90, &pb::ExportTelemetryRequest::default_instance()},
    Entry{91, &pb::ExportTelemetryResponse::default_instance()},
    Entry{92, &pb::ImportTelemetryRequest::default_instance()},
    Entry{93, &pb::ImportTelemetryResponse::default_instance()},
    Entry{94, &pb::TraceTelemetryFramesRequest::default_instance()},
    Entry{95, &pb::TraceTelemetryFramesResponse::default_instance()},
    Entry{96, &pb::DeleteTelemetryRequest::default_instance()},
    Entry{97, &pb::DeleteTelemetryResponse::default_instance()},
    Entry{98, &pb::DeactivateLicenseRequest::default_instance()},
    Entry{99, &pb::DeactivateLicenseResponse::default_instance()},
    Entry{100, &pb::CheckForUpdatesRequest::default_instance()},
    Entry{101, &pb::CheckForUpdatesResponse::default_instance()},
    Entry{102, &pb::SendStatisticsRequest::default_instance()},
    Entry{103, &pb::SendStatisticsResponse::default_instance()},
    Entry{106, &pb::GetParametersSelectionValuesRequest::default_instance()},
    Entry{107, &pb::GetParametersSelectionValuesResponse::default_instance()},
    Entry{108, &pb::GetAdsbBulbStatusRequest::default_instance()},
    Entry{109, &pb::GetAdsbBulbStatusResponse::default_instance()},
    Entry{110, &pb::CountTelemetryRequest::default_instance()},
    Entry{111, &pb::CountTelemetryResponse::default_instance()},
    Entry{112, &pb::CalculateSplineRequest::default_instance()},
    Entry{113, &pb::CalculateSplineResponse::default_instance()},
    Entry{114, &pb::ChangeRouteVehicleProfileRequest::default_instance()},
    Entry{115, &pb::ChangeRouteVehicleProfileResponse::default_instance()},
    Entry{116, &pb::GetNfzListRequest::default_instance()},
    Entry{117, &pb::GetNfzListResponse::default_instance()},
    Entry{118, &pb::SubmitUtmOperationRequest::default_instance()},
    Entry{119, &pb::SubmitUtmOperationResponse::default_instance()},
    Entry{120, &pb::GetCapabilitiesRequest::default_instance()},
    Entry{121, &pb::GetCapabilitiesResponse::default_instance()},
    Entry{124, &pb::GetMappingRequest::default_instance()},
    Entry{125, &pb::GetMappingResponse::default_instance()},
    Entry{126, &pb::GetVehicleTracksRequest::default_instance()},
    Entry{127, &pb::GetVehicleTracksResponse::default_instance()},
    Entry{128, &pb::GetNativeRouteRequest::default_instance()},
    Entry{129, &pb::GetNativeRouteResponse::default_instance()},
    Entry{130, &pb::GetLocationPassingTimeRequest::default_instance()},
    Entry{131, &pb::GetLocationPassingTimeResponse::default_instance()},
    Entry{132, &pb::GetPolygonAreaRequest::default_instance()},
    Entry{133, &pb::GetPolygonAreaResponse::default_instance()},
    Entry{134, &pb::SplitRouteBySegmentsRequest::default_instance()},
    Entry{135, &pb::SplitRouteBySegmentsResponse::default_instance()},
    Entry{136, &pb::SplitRouteByDistanceRequest::default_instance()},
    Entry{137, &pb::SplitRouteByDistanceResponse::default_instance()},
    Entry{138, &pb::JoinRouteRequest::default_instance()},
    Entry{139, &pb::JoinRouteResponse::default_instance()},
    Entry{140, &pb::ReconstructRouteRequest::default_instance()},
    Entry{141, &pb::ReconstructRouteResponse::default_instance()},
    Entry{146, &pb::SwapElevationOrderRequest::default_instance()},
    Entry{147, &pb::SwapElevationOrderResponse::default_instance()},
    Entry{148, &pb::DeleteVehicleTrackRequest::default_instance()},
    Entry{149, &pb::DeleteVehicleTrackResponse::default_instance()},
    Entry{150, &pb::MergeVehicleTrackRequest::default_instance()},
    Entry{151, &pb::MergeVehicleTrackResponse::default_instance()},
    Entry{152, &pb::CheckLocationRequest::default_instance()},
    Entry{153, &pb::CheckLocationResponse::default_instance()},
    Entry{154, &pb::SplitVehicleTrackRequest::default_instance()},
    Entry{155, &pb::SplitVehicleTrackResponse::default_instance()},
    Entry{156, &pb::GetVehicleVideoLogRequest::default_instance()},
    Entry{157, &pb::GetVehicleVideoLogResponse::default_instance()},
    Entry{158, &pb::ExportTelemetryStreamRequest::default_instance()},
    Entry{159, &pb::ExportTelemetryStreamResponse::default_instance()},
    Entry{160, &pb::ImportTelemetryStreamRequest::default_instance()},
    Entry{161, &pb::ImportTelemetryStreamResponse::default_instance()},
    Entry{162, &pb::GetElevationTilesRequest::default_instance()},
    Entry{163, &pb::GetElevationTilesResponse::default_instance()},
    Entry{164, &pb::ExportRouteToKmlRequest::default_instance()},
    Entry{165, &pb::ExportRouteToKmlResponse::default_instance()},
    Entry{168, &pb::GetTelemetrySnapshotRequest::default_instance()},
    Entry{169, &pb::GetTelemetrySnapshotResponse::default_instance()},
    Entry{170, &pb::GetElevationTilesV2Request::default_instance()},
    Entry{171, &pb::GetElevationTilesV2Response::default_instance()},
    Entry{172, &pb::ExportRouteToWpmlRequest::default_instance()},
    Entry{173, &pb::ExportRouteToWpmlResponse::default_instance()},
    Entry{174, &pb::SplitRouteByCorridorPointRequest::default_instance()},
    Entry{175, &pb::SplitRouteByCorridorPointResponse::default_instance()},
    Entry{176, &pb::GetElevationProfileV2Request::default_instance()},
    Entry{177, &pb::GetElevationProfileV2Response::default_instance()},
    Entry{178, &pb::GetChangelogRequest::default_instance()},
    Entry{179, &pb::GetChangelogResponse::default_instance()},
    Entry{180, &pb::IsTelemetryFieldRegisteredRequest::default_instance()},
    Entry{181, &pb::IsTelemetryFieldRegisteredResponse::default_instance()},
    Entry{182, &pb::ImportMissionOrRouteFromUgcsRequest::default_instance()},
    Entry{183, &pb::ImportMissionOrRouteFromUgcsResponse::default_instance()},
    Entry{184, &pb::ImportMissionFromUgcsRequest::default_instance()},
    Entry{185, &pb::ImportMissionFromUgcsResponse::default_instance()},
    Entry{186, &pb::ImportRouteFromUgcsRequest::default_instance()},
    Entry{187, &pb::ImportRouteFromUgcsResponse::default_instance()},
    Entry{188, &pb::ImportProfilesFromUgcsRequest::default_instance()},
    Entry{189, &pb::ImportProfilesFromUgcsResponse::default_instance()},
    Entry{190, &pb::ImportRouteFromCsvRequest::default_instance()},
    Entry{191, &pb::ImportRouteFromCsvResponse::default_instance()},
    Entry{192, &pb::ImportRouteFromKmlRequest::default_instance()},
    Entry{193, &pb::ImportRouteFromKmlResponse::default_instance()},
    Entry{194, &pb::ExportMissionToUgcsRequest::default_instance()},
    Entry{195, &pb::ExportMissionToUgcsResponse::default_instance()},
    Entry{196, &pb::ExportRouteToUgcsRequest::default_instance()},
    Entry{197, &pb::ExportRouteToUgcsResponse::default_instance()},
    Entry{198, &pb::ExportProfilesToUgcsRequest::default_instance()},
    Entry{199, &pb::ExportProfilesToUgcsResponse::default_instance()},
    Entry{200, &pb::SendFeedbackRequest::default_instance()},
    Entry{201, &pb::SendFeedbackResponse::default_instance()},
    Entry{202, &pb::GetRouteListRequest::default_instance()},
    Entry{203, &pb::GetRouteListResponse::default_instance()},
    Entry{204, &pb::ConfigureAnalyticsRequest::default_instance()},
    Entry{205, &pb::EmptyResponse::default_instance()},
    Entry{206, &pb::ReadAnalyticsConfigurationRequest::default_instance()},
    Entry{207, &pb::ReadAnalyticsConfigurationResponse::default_instance()},
    Entry{208, &pb::SendAnalyticsEventRequest::default_instance()},
    Entry{209, &pb::GetFreeUsageCodeRequest::default_instance()},
    Entry{210, &pb::StartFreeUsageRequest::default_instance()},
    Entry{211, &pb::CheckPermissionRequest::default_instance()},
    Entry{212, &pb::ResolveGsdByAltitudeAglRequest::default_instance()},
    Entry{213, &pb::ResolveGsdByAltitudeAmslRequest::default_instance()},
    Entry{214, &pb::ResolveAltitudeAglByGsdRequest::default_instance()},
    Entry{215, &pb::ResolveAltitudeAmslByGsdRequest::default_instance()},
    Entry{216, &pb::SingleValueResponse::default_instance()},
    Entry{217, &pb::GetDeviceIdRequest::default_instance()},
    Entry{218, &pb::GetDeviceIdResponse::default_instance()},
    Entry{227, &pb::GetLicenseImprovementWindowContentRequest::default_instance()},
    Entry{228, &pb::GetLicenseImprovementWindowContentResponse::default_instance()},
    Entry{231, &pb::UploadRouteRequest2::default_instance()},
    Entry{500, &pb::PingRequest::default_instance()},
};

} // namespace

const google::protobuf::Message *HciMessageTypes::prototype(int32_t number)
{
    // A direct table over 0..500 (the decoder asks for every frame), built once from kTable.
    static const auto byNumber = [] {
        std::array<const google::protobuf::Message *, 501> table{};
        for (const Entry &e : kTable)
            table[size_t(e.number)] = e.prototype;
        return table;
    }();
    return number >= 0 && size_t(number) < byNumber.size() ? byNumber[size_t(number)] : nullptr;
}

std::optional<int32_t> HciMessageTypes::number(const google::protobuf::Descriptor *descriptor)
{
    // Built once, read-only afterwards (thread-safe static initialisation); the encoder asks on every send.
    static const std::unordered_map<const google::protobuf::Descriptor *, int32_t> byDescriptor = [] {
        std::unordered_map<const google::protobuf::Descriptor *, int32_t> map;
        for (const Entry &e : kTable)
            map.emplace(e.prototype->GetDescriptor(), e.number);
        return map;
    }();
    const auto it = byDescriptor.find(descriptor);
    return it != byDescriptor.end() ? std::optional(it->second) : std::nullopt;
}

std::string_view HciMessageTypes::name(int32_t number)
{
    const auto *p = prototype(number);
    return p ? std::string_view(p->GetDescriptor()->name()) : std::string_view();
}

std::optional<int32_t> HciMessageTypes::numberOf(std::string_view name)
{
    static const std::unordered_map<std::string_view, int32_t> byName = [] {
        std::unordered_map<std::string_view, int32_t> map;
        for (const Entry &e : kTable)
            map.emplace(e.prototype->GetDescriptor()->name(), e.number);
        return map;
    }();
    const auto it = byName.find(name);
    return it != byName.end() ? std::optional(it->second) : std::nullopt;
}

std::optional<int32_t> HciMessageTypes::responseFor(int32_t requestNumber)
{
    constexpr std::string_view suffix = "Request";
    const std::string_view request = name(requestNumber);
    if (request.size() <= suffix.size() || request.substr(request.size() - suffix.size()) != suffix)
        return std::nullopt;
    std::string response(request.substr(0, request.size() - suffix.size()));
    response += "Response";
    return numberOf(response);
}

size_t HciMessageTypes::count()
{
    return kTable.size();
}

int32_t HciMessageTypes::numberAt(size_t index)
{
    return kTable.at(index).number;
}

} // namespace sortie::hci
