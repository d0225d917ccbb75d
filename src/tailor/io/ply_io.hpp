#pragma once
/// @file
/// Stanford PLY reading and writing (ASCII and binary, positions and triangle faces):
/// the format vocabulary, the reader and the writer.

#include "tailor/io/ply_format.hpp"
#include "tailor/io/ply_reader.hpp"
#include "tailor/io/ply_writer.hpp"
