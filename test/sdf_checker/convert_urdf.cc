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

// Load a URDF with the reference parser, which converts it to SDF as Gazebo does, and
// print the SDF it made on stdout. Print every error on stderr and exit 1 if there is one.
#include <iostream>
#include <sdf/sdf.hh>

int main(int argc, char ** argv)
{
  if (argc != 2) {
    std::cerr << "usage: convert_urdf FILE" << std::endl;
    return 2;
  }
  sdf::Root root;
  sdf::Errors errors = root.Load(argv[1]);
  for (const auto & error : errors) {
    std::cerr << error << std::endl;
  }
  if (!errors.empty()) {
    return 1;
  }
  std::cout << root.Element()->ToString("") << std::endl;
  return 0;
}
