// Internal: the GPU side of 3D scenes: the mesh shader (soft shading), mesh
// upload to vertex buffers, and the per-process cache of unit-shape meshes.
#pragma once

#include "gl.h"
#include "rigid/render/mesh.h"
#include "rigid/render/scene3d.h"

namespace rigid::render::detail {

/// A mesh in GL buffers, ready for glDrawElements.
struct GpuMesh {
  GLuint vao = 0, vbo = 0, ibo = 0;
  GLsizei count = 0;
};

/// The lit-mesh shader program and its uniform locations.
struct MeshProgram {
  GLuint program = 0;
  GLint mvp = -1, mv = -1, nmat = -1, color = -1, spec = -1, shininess = -1, ortho = -1, lit = -1;
};

/// Copies a mesh into new GL buffers (positions and normals interleaved).
GpuMesh upload(const Mesh& m);
/// Frees the buffers of an uploaded mesh.
void release(GpuMesh& g);
/// The process's mesh program, compiled on first use.
MeshProgram& mesh_program();
/// The unit mesh of a shape at a segment count, uploaded once per process.
const GpuMesh& unit_mesh(Scene3D::Shape shape, int segments, double torus_minor);

}  // namespace rigid::render::detail
