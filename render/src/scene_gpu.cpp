// The GPU side of 3D scenes: shaders, mesh upload, unit-mesh cache.
#include "scene_gpu.h"

#include <map>
#include <tuple>
#include <vector>

#include "scene_shapes.h"

namespace rigid::render::detail {

namespace {

const char* kMeshVertex = R"(
in vec3 a_pos;
in vec3 a_normal;
uniform mat4 u_mvp;
uniform mat4 u_mv;
uniform mat3 u_nmat;
out vec3 v_n;
out vec3 v_p;
void main() {
  gl_Position = u_mvp * vec4(a_pos, 1.0);
  v_p = (u_mv * vec4(a_pos, 1.0)).xyz;
  v_n = u_nmat * a_normal;
}
)";

// Soft shading in view space: hemispheric ambient (sky above, ground below),
// Lambert from a key light (upper left, in front) and a weaker fill (right),
// and a mild Blinn-Phong highlight from the key. Back faces are lit as their
// own side so open surfaces and the insides of translucent shells look right.
const char* kMeshFragment = R"(
in vec3 v_n;
in vec3 v_p;
uniform vec4 u_color;
uniform float u_spec;
uniform float u_shininess;
uniform int u_ortho;
uniform int u_lit;
out vec4 frag;
void main() {
  if (u_lit == 0) {
    frag = u_color;
    return;
  }
  vec3 n = normalize(v_n);
  if (!gl_FrontFacing) n = -n;
  vec3 v = u_ortho == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-v_p);
  const vec3 key = normalize(vec3(-0.45, 0.65, 0.62));
  const vec3 fill = normalize(vec3(0.75, -0.15, 0.45));
  float hemi = 0.5 + 0.5 * n.y;
  float ambient = mix(0.30, 0.46, hemi);
  float diffuse = 0.55 * max(dot(n, key), 0.0) + 0.20 * max(dot(n, fill), 0.0);
  float spec = u_spec * pow(max(dot(n, normalize(key + v)), 0.0), u_shininess);
  vec3 c = u_color.rgb * (ambient + diffuse) + vec3(spec);
  frag = vec4(min(c, vec3(1.0)), u_color.a);
}
)";

}  // namespace

GpuMesh upload(const Mesh& m) {
  GpuMesh g;
  std::vector<float> data;
  data.reserve(m.positions.size() * 6);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    data.insert(data.end(), {m.positions[i].x(), m.positions[i].y(), m.positions[i].z()});
    data.insert(data.end(), {m.normals[i].x(), m.normals[i].y(), m.normals[i].z()});
  }
  auto& gl = detail::gl;
  gl.GenVertexArrays(1, &g.vao);
  gl.BindVertexArray(g.vao);
  gl.GenBuffers(1, &g.vbo);
  gl.BindBuffer(GL_ARRAY_BUFFER, g.vbo);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
                GL_STATIC_DRAW);
  gl.GenBuffers(1, &g.ibo);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo);
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                static_cast<GLsizeiptr>(m.indices.size() * sizeof(std::uint32_t)), m.indices.data(),
                GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                         reinterpret_cast<const void*>(3 * sizeof(float)));
  gl.BindVertexArray(0);
  g.count = static_cast<GLsizei>(m.indices.size());
  return g;
}

void release(GpuMesh& g) {
  auto& gl = detail::gl;
  GLuint bufs[] = {g.vbo, g.ibo};
  gl.DeleteBuffers(2, bufs);
  gl.DeleteVertexArrays(1, &g.vao);
  g = GpuMesh{};
}

MeshProgram& mesh_program() {
  static MeshProgram* p = [] {
    auto* m = new MeshProgram;
    const char* attrs[] = {"a_pos", "a_normal"};
    m->program = build_program(kMeshVertex, kMeshFragment, attrs, 2);
    auto& gl = detail::gl;
    m->mvp = gl.GetUniformLocation(m->program, "u_mvp");
    m->mv = gl.GetUniformLocation(m->program, "u_mv");
    m->nmat = gl.GetUniformLocation(m->program, "u_nmat");
    m->color = gl.GetUniformLocation(m->program, "u_color");
    m->spec = gl.GetUniformLocation(m->program, "u_spec");
    m->shininess = gl.GetUniformLocation(m->program, "u_shininess");
    m->ortho = gl.GetUniformLocation(m->program, "u_ortho");
    m->lit = gl.GetUniformLocation(m->program, "u_lit");
    return m;
  }();
  return *p;
}

// Unit meshes, made once per process per (shape, segments, torus ratio).
const GpuMesh& unit_mesh(Scene3D::Shape shape, int segments, double torus_minor) {
  using Key = std::tuple<int, int, int>;
  static std::map<Key, GpuMesh> cache;
  const int ratio = torus_ratio_key(shape, torus_minor);
  const Key key{static_cast<int>(shape), segments, ratio};
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  return cache.emplace(key, upload(unit_shape_mesh(shape, segments, ratio))).first->second;
}

}  // namespace rigid::render::detail
