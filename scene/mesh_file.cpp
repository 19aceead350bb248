// mesh_file.cpp: a profile scene's mesh from a Wavefront OBJ file (see
// mesh_file.h).
#include "scene/mesh_file.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "scene/input_error.h"

namespace st {

namespace {

constexpr size_t kMaxVertices = 4u << 20;  // corners after triangulation: 64 MB of attributes

struct Corner {
    long v = 0, vt = 0, vn = 0;  // 1-based, 0: absent
};

// "v", "v/vt", "v//vn" or "v/vt/vn"; negative indices count from the end.
bool parse_corner(const std::string& token, Corner& c) {
    long* slots[3] = {&c.v, &c.vt, &c.vn};
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
        const size_t slash = token.find('/', start);
        const std::string part = token.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
        if (!part.empty()) {
            size_t used = 0;
            try {
                *slots[k] = std::stol(part, &used);
            } catch (...) {
                return false;
            }
            if (used != part.size() || *slots[k] == 0) return false;
        } else if (k == 0) {
            return false;
        }
        if (slash == std::string::npos) return true;
        start = slash + 1;
    }
    return false;  // more than three parts
}

}  // namespace

ProfileMesh read_mesh_file(const std::string& path, const std::string& field) {
    auto fail = [&](const std::string& what) { throw InputError("field '" + field + "': " + path + ": " + what); };
    std::ifstream in(path);
    if (!in) fail("cannot read it");
    std::vector<glm::dvec3> positions, normals;
    std::vector<glm::dvec2> uvs;
    std::vector<std::vector<Corner>> faces;
    std::vector<int> face_lines;
    std::string line;
    int number = 0;
    auto finite = [](double x) { return std::isfinite(x); };
    while (std::getline(in, line)) {
        ++number;
        std::istringstream s(line);
        std::string tag;
        if (!(s >> tag) || tag[0] == '#') continue;
        const std::string at = "line " + std::to_string(number) + ": ";
        if (tag == "v" || tag == "vn") {
            glm::dvec3 p;
            if (!(s >> p.x >> p.y >> p.z) || !finite(p.x) || !finite(p.y) || !finite(p.z))
                fail(at + "'" + tag + "' needs three finite numbers");
            (tag == "v" ? positions : normals).push_back(p);
        } else if (tag == "vt") {
            glm::dvec2 t;
            if (!(s >> t.x >> t.y) || !finite(t.x) || !finite(t.y)) fail(at + "'vt' needs two finite numbers");
            if (t.x < 0 || t.x > 1 || t.y < 0 || t.y > 1)
                fail(at + "texture coordinates outside [0, 1]: the layout must lie on the texture-space targets");
            uvs.push_back(t);
        } else if (tag == "f") {
            std::vector<Corner> face;
            std::string token;
            while (s >> token) {
                Corner c;
                if (!parse_corner(token, c)) fail(at + "a face corner '" + token + "' is not v/vt/vn");
                face.push_back(c);
            }
            if (face.size() < 3) fail(at + "a face needs three corners or more");
            faces.push_back(std::move(face));
            face_lines.push_back(number);
        }
        // Other statements (o, g, s, usemtl, mtllib, l) do not change the surface.
    }
    if (faces.empty()) fail("no faces");
    ProfileMesh m;
    m.vertices.attribute_count = 3;
    glm::dvec3 lo(1e300), hi(-1e300);
    auto resolve = [&](long index, size_t count, int face_line, const char* what) {
        const long i = index < 0 ? long(count) + index : index - 1;
        if (i < 0 || size_t(i) >= count)
            fail("line " + std::to_string(face_line) + ": " + what + " index " + std::to_string(index) +
                 " names none of the " + std::to_string(count) + " given");
        return size_t(i);
    };
    for (size_t f = 0; f < faces.size(); ++f) {
        const std::vector<Corner>& face = faces[f];
        const int face_line = face_lines[f];
        glm::dvec3 p[3];
        for (int k = 0; k < 3; ++k) p[k] = positions[resolve(face[size_t(k)].v, positions.size(), face_line, "vertex")];
        const glm::dvec3 flat = glm::cross(p[1] - p[0], p[2] - p[0]);
        // A fan of triangles over the polygon.
        for (size_t k = 1; k + 1 < face.size(); ++k) {
            for (const size_t corner : {size_t(0), k, k + 1}) {
                const Corner& c = face[corner];
                if (c.vt == 0)
                    fail("line " + std::to_string(face_line) +
                         ": a face corner without texture coordinates; the irradiance pass draws the mesh at its uv");
                const glm::dvec3 pos = positions[resolve(c.v, positions.size(), face_line, "vertex")];
                const glm::dvec2 uv = uvs[resolve(c.vt, uvs.size(), face_line, "texture coordinate")];
                glm::dvec3 n = c.vn ? normals[resolve(c.vn, normals.size(), face_line, "normal")] : flat;
                if (!(glm::length(n) > 0))
                    fail("line " + std::to_string(face_line) + ": a zero normal (or a degenerate face without normals)");
                n = glm::normalize(n);
                m.vertices.data.push_back(glm::vec4(glm::vec3(pos), 1.0f));
                m.vertices.data.push_back(glm::vec4(glm::vec3(n), 0.0f));
                m.vertices.data.push_back(glm::vec4(float(uv.x), float(uv.y), 0.0f, 1.0f));
                m.indices.push_back(uint32_t(m.indices.size()));
                lo = glm::min(lo, pos), hi = glm::max(hi, pos);
                if (m.indices.size() > kMaxVertices) fail("more than " + std::to_string(kMaxVertices) + " triangle corners");
            }
        }
    }
    for (int k = 0; k < 8; ++k)
        m.bounds.push_back(glm::dvec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z));
    return m;
}

}  // namespace st
