#ifndef UBII_MESSAGES_HPP
#define UBII_MESSAGES_HPP

// The Ubi-Interact schema as protobuf C++ classes, generated from libubii's own .proto files
// (proto/): ubii::<package>::<Message>, e.g. ubii::dataStructure::Vector3,
// ubii::services::ServiceRequest, ubii::sessions::Session. The short aliases below name the types
// an application meets most. Helpers build the small value types in one expression.

#include <cstdint>
#include <string>

#include "ubii/messages/clients/client.pb.h"
#include "ubii/messages/dataStructure/color.pb.h"
#include "ubii/messages/dataStructure/image.pb.h"
#include "ubii/messages/dataStructure/keyEvent.pb.h"
#include "ubii/messages/dataStructure/lists.pb.h"
#include "ubii/messages/dataStructure/matrix3x2.pb.h"
#include "ubii/messages/dataStructure/matrix4x4.pb.h"
#include "ubii/messages/dataStructure/mouseEvent.pb.h"
#include "ubii/messages/dataStructure/myoEvent.pb.h"
#include "ubii/messages/dataStructure/object2d.pb.h"
#include "ubii/messages/dataStructure/object3d.pb.h"
#include "ubii/messages/dataStructure/pose2d.pb.h"
#include "ubii/messages/dataStructure/pose3d.pb.h"
#include "ubii/messages/dataStructure/quaternion.pb.h"
#include "ubii/messages/dataStructure/touchEvent.pb.h"
#include "ubii/messages/dataStructure/vector2.pb.h"
#include "ubii/messages/dataStructure/vector3.pb.h"
#include "ubii/messages/dataStructure/vector4.pb.h"
#include "ubii/messages/devices/component.pb.h"
#include "ubii/messages/devices/device.pb.h"
#include "ubii/messages/general/error.pb.h"
#include "ubii/messages/general/success.pb.h"
#include "ubii/messages/processing/lockstepProcessing.pb.h"
#include "ubii/messages/processing/processingModule.pb.h"
#include "ubii/messages/servers/server.pb.h"
#include "ubii/messages/services/service.pb.h"
#include "ubii/messages/services/serviceReply.pb.h"
#include "ubii/messages/services/serviceRequest.pb.h"
#include "ubii/messages/sessions/session.pb.h"
#include "ubii/messages/topicData/topicDataRecord.pb.h"

namespace ubii
{

using Vector2 = dataStructure::Vector2;
using Vector3 = dataStructure::Vector3;
using Vector4 = dataStructure::Vector4;
using Quaternion = dataStructure::Quaternion;
using Color = dataStructure::Color;
using Pose2D = dataStructure::Pose2D;
using Pose3D = dataStructure::Pose3D;
using Matrix3x2 = dataStructure::Matrix3x2;
using Matrix4x4 = dataStructure::Matrix4x4;
using Image2D = dataStructure::Image2D;
using Image2DList = dataStructure::Image2DList;
using Object2D = dataStructure::Object2D;
using Object2DList = dataStructure::Object2DList;
using Object3D = dataStructure::Object3D;
using Object3DList = dataStructure::Object3DList;
using DoubleList = dataStructure::DoubleList;
using FloatList = dataStructure::FloatList;
using Int32List = dataStructure::Int32List;
using BoolList = dataStructure::BoolList;
using StringList = dataStructure::StringList;
using KeyEvent = dataStructure::KeyEvent;
using MouseEvent = dataStructure::MouseEvent;
using TouchEvent = dataStructure::TouchEvent;
using ErrorMessage = general::Error; // ubii::Error is the exception base class
using Success = general::Success;
using Client = clients::Client;
using ClientList = clients::ClientList;
using Device = devices::Device;
using DeviceList = devices::DeviceList;
using Component = devices::Component;
using Server = servers::Server;
using Service = services::Service;
using ServiceList = services::ServiceList;
using ServiceRequest = services::ServiceRequest;
using ServiceReply = services::ServiceReply;
using Session = sessions::Session;
using SessionList = sessions::SessionList;
using IOMapping = sessions::IOMapping;
using TopicInputMapping = sessions::TopicInputMapping;
using TopicOutputMapping = sessions::TopicOutputMapping;
using TopicMux = devices::TopicMux;
using TopicDemux = devices::TopicDemux;
using ProcessingModuleSpec = processing::ProcessingModule; // ubii::ProcessingModule is the class
using ProcessingModuleSpecList = processing::ProcessingModuleList;
using ModuleIOSpec = processing::ModuleIO;
using LockstepProcessingRequest = processing::LockstepProcessingRequest;
using LockstepProcessingReply = processing::LockstepProcessingReply;
using TopicDataRecord = topicData::TopicDataRecord;

Vector2 vector2(double x, double y);
Vector3 vector3(double x, double y, double z);
Vector4 vector4(double x, double y, double z, double w);
Quaternion quaternion(double x, double y, double z, double w);
Color color(double r, double g, double b, double a = 1.0);

} // namespace ubii

#endif
