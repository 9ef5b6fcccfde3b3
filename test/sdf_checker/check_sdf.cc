// Copyright 2026 urdfgenpy_ros contributors
//
// Licensed under the Apache License, Version 2.0 (the "License");
// you may not use this file except in compliance with the License.
// You may obtain a copy of the License at
//
//     http://www.apache.org/licenses/LICENSE-2.0
//
// Unless required by applicable law or agreed to in writing, software
// distributed under the License is distributed on an "AS IS" BASIS,
// WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
// See the License for the specific language governing permissions and
// limitations under the License.

// Load an SDF (or URDF, which libsdformat converts) with the reference parser. Print every
// error on stderr and exit 1 if there is one; else print, per link, its pose in the model
// frame ("link NAME x y z qw qx qy qz"), its inertial ("inertial LINK mass cx cy cz" and the
// principal moments) and its sensors ("sensor LINK NAME TYPE"), then each frame of the model
// with its pose in the model frame and its link ("frame NAME x y z qw qx qy qz LINK"). With
// --sdf, print the SDF
// the parser made instead (for a URDF, libsdformat's conversion, as Gazebo sees it).
#include <iostream>
#include <string>
#include <sdf/sdf.hh>

int main(int argc, char ** argv)
{
  const bool print_sdf = argc == 3 && std::string(argv[1]) == "--sdf";
  if (argc != 2 && !print_sdf) {
    std::cerr << "usage: check_sdf [--sdf] FILE" << std::endl;
    return 2;
  }
  sdf::Root root;
  sdf::Errors errors = root.Load(argv[argc - 1]);
  for (const auto & error : errors) {
    std::cerr << error << std::endl;
  }
  if (!errors.empty()) {
    return 1;
  }
  if (print_sdf) {
    std::cout << root.Element()->ToString("") << std::endl;
    return 0;
  }
  const sdf::Model * model = root.Model();
  if (model == nullptr) {
    std::cerr << "no model" << std::endl;
    return 1;
  }
  std::cout.precision(17);
  for (uint64_t i = 0; i < model->LinkCount(); ++i) {
    const sdf::Link * link = model->LinkByIndex(i);
    ignition::math::Pose3d pose;
    sdf::Errors poseErrors = link->SemanticPose().Resolve(pose, "__model__");
    for (const auto & error : poseErrors) {
      std::cerr << error << std::endl;
    }
    if (!poseErrors.empty()) {
      return 1;
    }
    std::cout << "link " << link->Name() << " " << pose.Pos().X() << " " << pose.Pos().Y() <<
      " " << pose.Pos().Z() << " " << pose.Rot().W() << " " << pose.Rot().X() << " " <<
      pose.Rot().Y() << " " << pose.Rot().Z() << std::endl;
    const ignition::math::Inertiald & inertial = link->Inertial();
    ignition::math::Vector3d moments = inertial.MassMatrix().PrincipalMoments();
    std::cout << "inertial " << link->Name() << " " << inertial.MassMatrix().Mass() << " " <<
      inertial.Pose().Pos().X() << " " << inertial.Pose().Pos().Y() << " " <<
      inertial.Pose().Pos().Z() << " " << moments.X() << " " << moments.Y() << " " <<
      moments.Z() << std::endl;
    for (uint64_t v = 0; v < link->VisualCount(); ++v) {
      const sdf::Visual * visual = link->VisualByIndex(v);
      ignition::math::Pose3d placed;
      sdf::Errors visualErrors = visual->SemanticPose().Resolve(placed, link->Name());
      if (visualErrors.empty()) {
        std::cout << "visual " << link->Name() << " " << visual->Name() << " " <<
          placed.Pos().X() << " " << placed.Pos().Y() << " " << placed.Pos().Z() << " " <<
          placed.Rot().W() << " " << placed.Rot().X() << " " << placed.Rot().Y() << " " <<
          placed.Rot().Z() << std::endl;
      }
    }
    for (uint64_t s = 0; s < link->SensorCount(); ++s) {
      const sdf::Sensor * sensor = link->SensorByIndex(s);
      std::cout << "sensor " << link->Name() << " " << sensor->Name() << " " <<
        sensor->TypeStr() << std::endl;
    }
  }
  for (uint64_t f = 0; f < model->FrameCount(); ++f) {
    const sdf::Frame * frame = model->FrameByIndex(f);
    ignition::math::Pose3d pose;
    std::string link;
    sdf::Errors frameErrors = frame->SemanticPose().Resolve(pose, "__model__");
    sdf::Errors linkErrors = frame->ResolveAttachedToBody(link);
    for (const auto & error : frameErrors) {
      std::cerr << error << std::endl;
    }
    for (const auto & error : linkErrors) {
      std::cerr << error << std::endl;
    }
    if (!frameErrors.empty() || !linkErrors.empty()) {
      return 1;
    }
    std::cout << "frame " << frame->Name() << " " << pose.Pos().X() << " " << pose.Pos().Y() <<
      " " << pose.Pos().Z() << " " << pose.Rot().W() << " " << pose.Rot().X() << " " <<
      pose.Rot().Y() << " " << pose.Rot().Z() << " " << link << std::endl;
  }
  return 0;
}
