// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_ERRORS_H
#define CGAL_DF_L1_SKELETON_ERRORS_H

/// \file errors.h
/// The exception types thrown by the package. Every failure the package detects
/// is reported by one of them, with a message that names what is wrong.

#include <stdexcept>
#include <string>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// Thrown when the input point set or a parameter cannot be processed
/// (empty input, non-finite coordinate, parameter out of range...).
class Invalid_input : public std::invalid_argument
{
public:
  /// \param what the message, naming the input and what is wrong
  explicit Invalid_input(const std::string& what) : std::invalid_argument(what) {}
};

/// \ingroup PkgDFL1SkeletonRef
/// Thrown by the readers when a file cannot be opened or parsed. The message
/// names the file and, where it applies, the line or element number.
class Read_error : public std::runtime_error
{
public:
  /// \param what the message, naming the input and what is wrong
  explicit Read_error(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgDFL1SkeletonRef
/// Thrown by the writers when an output file cannot be written completely.
/// The destination is then left untouched.
class Write_error : public std::runtime_error
{
public:
  /// \param what the message, naming the input and what is wrong
  explicit Write_error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_ERRORS_H
