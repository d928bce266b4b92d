// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// libFuzzer target: the XYZ parser (.xyz, .pts, .txt) of the point cloud readers on arbitrary bytes.

#include "fuzz_common.h"

#include <CGAL/DF_L1_skeleton/IO/internal/read_xyz.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  return df_l1_fuzz::run(data, size, [](std::string_view buf, const std::string& name,
                                        df_l1_fuzz::Cloud& pc) {
    CGAL::DF_L1::internal::point_cloud_reader::parse_xyz(buf, name, pc);
  });
}
