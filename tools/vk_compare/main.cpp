// aapat-vk-compare: renders a scene on a GPU with an exported pattern
// (VK_EXT_sample_locations and the export's own GLSL resolve) and compares
// it with `aapat render` of the same pattern on the CPU.
//
//   aapat-vk-compare EXPORT.txt SCENE.json [--size 64x64] [--gpu gpu.png] [--cpu cpu.png]
//
// EXPORT is `aapat export PATTERN --api vulkan` output; SCENE is an aapat
// scene file of convex polygons (drawn in order, as aapat paints them).
// Exit status: 0 compared (figures printed), 1 error, 77 no Vulkan device
// that can place these samples (no VK_EXT_sample_locations, and the
// positions are not the standard ones).
#include <fmt/format.h>
#include <vulkan/vulkan.h>

#include <unistd.h>
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <cstring>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "aapat/core/filter_catalog.h"
#include "aapat/generate/catalog.h"
#include "aapat/io/api_export.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/png_image.h"
#include "aapat/io/scene_json.h"
#include "aapat/render/image_error.h"
#include "aapat/render/renderer.h"

namespace {

using aapat::Error;

constexpr int kNoDevice = 77;

// A Vulkan structure zeroed, with its type set.
template <class T>
T vk(VkStructureType type) {
  T x{};
  x.sType = type;
  return x;
}

struct NoDevice : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void check(VkResult r, const char* what) {
  if (r != VK_SUCCESS)
    throw Error(fmt::format("{} failed (VkResult {})", what, static_cast<int>(r)));
}

// GLSL to SPIR-V with glslangValidator (Debian's glslang-tools).
std::vector<uint32_t> compile(const std::string& source, const char* stage) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string in = (dir / fmt::format("aapat-vk-{}.{}", ::getpid(), stage)).string();
  const std::string out = in + ".spv";
  std::ofstream(in) << source;
  const std::string cmd =
      fmt::format("glslangValidator -V --quiet -S {} -o '{}' '{}' >&2", stage, out, in);
  const int rc = std::system(cmd.c_str());
  std::filesystem::remove(in);
  if (rc != 0) throw Error(fmt::format("glslangValidator could not compile the {} shader", stage));
  const std::string bytes = aapat::read_file(out, "SPIR-V");
  std::filesystem::remove(out);
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

// The GLSL part of an export: from the resolve comment to the end.
std::string resolve_glsl(const std::string& text) {
  const auto at = text.find("// Resolve:");
  if (at == std::string::npos || text.find("sampler2DMS") == std::string::npos)
    throw Error("the export has no GLSL resolve (export with --api vulkan, or --shader glsl)");
  return text.substr(at);
}

// Vulkan's standard sample locations: the catalog's msaa-N (the same table as
// Direct3D's), laid out as Vulkan sees them.
std::vector<aapat::LatticePoint> standard_locations(int count) {
  try {
    return aapat::hardware_layout(aapat::catalog_pattern(fmt::format("msaa-{}", count)),
                                  aapat::api_profile("vulkan"))
        .positions[0];
  } catch (const Error&) {
    return {};
  }
}

struct Gpu {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t family = 0;
  bool sample_locations = false;
  std::string name;
  ~Gpu() {
    if (device) vkDestroyDevice(device, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

void open_gpu(Gpu& g) {
  auto app = vk<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = "aapat-vk-compare";
  app.apiVersion = VK_API_VERSION_1_1;
  auto ici = vk<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  ici.pApplicationInfo = &app;
  if (vkCreateInstance(&ici, nullptr, &g.instance) != VK_SUCCESS)
    throw NoDevice("no Vulkan instance (is a Vulkan driver installed?)");
  uint32_t n = 0;
  vkEnumeratePhysicalDevices(g.instance, &n, nullptr);
  std::vector<VkPhysicalDevice> devices(n);
  vkEnumeratePhysicalDevices(g.instance, &n, devices.data());
  if (devices.empty()) throw NoDevice("no Vulkan device");
  // Prefer a device with VK_EXT_sample_locations.
  for (VkPhysicalDevice d : devices) {
    uint32_t m = 0;
    vkEnumerateDeviceExtensionProperties(d, nullptr, &m, nullptr);
    std::vector<VkExtensionProperties> ext(m);
    vkEnumerateDeviceExtensionProperties(d, nullptr, &m, ext.data());
    bool has = false;
    for (const auto& e : ext)
      has = has || std::strcmp(e.extensionName, VK_EXT_SAMPLE_LOCATIONS_EXTENSION_NAME) == 0;
    if (!g.physical || (has && !g.sample_locations)) {
      g.physical = d;
      g.sample_locations = has;
    }
  }
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(g.physical, &props);
  g.name = props.deviceName;
  uint32_t qn = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(g.physical, &qn, nullptr);
  std::vector<VkQueueFamilyProperties> qs(qn);
  vkGetPhysicalDeviceQueueFamilyProperties(g.physical, &qn, qs.data());
  bool found = false;
  for (uint32_t i = 0; i < qn && !found; ++i)
    if ((qs[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (qs[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) {
      g.family = i;
      found = true;
    }
  if (!found) throw NoDevice("no graphics and compute queue");
  const float priority = 1;
  auto qci = vk<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  qci.queueFamilyIndex = g.family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkPhysicalDeviceFeatures features{};
  features.sampleRateShading = VK_FALSE;
  const char* ext_name = VK_EXT_SAMPLE_LOCATIONS_EXTENSION_NAME;
  auto dci = vk<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.enabledExtensionCount = g.sample_locations ? 1 : 0;
  dci.ppEnabledExtensionNames = &ext_name;
  dci.pEnabledFeatures = &features;
  check(vkCreateDevice(g.physical, &dci, nullptr, &g.device), "vkCreateDevice");
  vkGetDeviceQueue(g.device, g.family, 0, &g.queue);
}

uint32_t memory_type(const Gpu& g, uint32_t bits, VkMemoryPropertyFlags want) {
  VkPhysicalDeviceMemoryProperties mp;
  vkGetPhysicalDeviceMemoryProperties(g.physical, &mp);
  for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
  throw Error("no suitable memory type");
}

VkDeviceMemory bind_memory(const Gpu& g, VkMemoryRequirements req, VkMemoryPropertyFlags want) {
  auto ai = vk<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = memory_type(g, req.memoryTypeBits, want);
  VkDeviceMemory m;
  check(vkAllocateMemory(g.device, &ai, nullptr, &m), "vkAllocateMemory");
  return m;
}

VkShaderModule shader_module(const Gpu& g, const std::vector<uint32_t>& spirv) {
  auto ci = vk<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  ci.codeSize = spirv.size() * 4;
  ci.pCode = spirv.data();
  VkShaderModule m;
  check(vkCreateShaderModule(g.device, &ci, nullptr, &m), "vkCreateShaderModule");
  return m;
}

struct Vertex {
  float x, y, grey;
};

// The scene's polygons as triangles in NDC (fans; the scene file's polygons must be convex).
std::vector<Vertex> triangles(const aapat::ShapesScene& s, int w, int h) {
  std::vector<Vertex> out;
  for (const auto& shape : s.shapes) {
    if (shape.polygon.empty())
      throw Error("aapat-vk-compare draws polygons only (a circle is in the scene)");
    auto ndc = [&](aapat::Vec2 p) {
      // Pixel (i, j) (y up, centred on integers) is framebuffer pixel (i, h - 1 - j).
      const double fx = p.x + 0.5, fy = h - 0.5 - p.y;
      return Vertex{static_cast<float>(2 * fx / w - 1), static_cast<float>(2 * fy / h - 1),
                    static_cast<float>(shape.grey)};
    };
    for (size_t k = 1; k + 1 < shape.polygon.size(); ++k) {
      out.push_back(ndc(shape.polygon[0]));
      out.push_back(ndc(shape.polygon[k]));
      out.push_back(ndc(shape.polygon[k + 1]));
    }
  }
  return out;
}

const char* kVertexShader = R"(#version 450
layout(location = 0) in vec2 pos;
layout(location = 1) in float grey;
layout(location = 0) out float v_grey;
void main() { gl_Position = vec4(pos, 0.0, 1.0); v_grey = grey; }
)";

const char* kFragmentShader = R"(#version 450
layout(location = 0) in flat float v_grey;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(v_grey, v_grey, v_grey, 1.0); }
)";

// The values the GPU resolved, rows top-down.
std::vector<float> render_on_gpu(Gpu& g, const aapat::HardwareLayout& L, const std::string& glsl,
                                 const aapat::ShapesScene& scene, int w, int h) {
  const auto samples = static_cast<VkSampleCountFlagBits>(L.sample_count);
  std::vector<VkSampleLocationEXT> locations;
  for (int p = 0; p < L.grid_w * L.grid_h; ++p)
    for (int i = 0; i < L.sample_count; ++i) {
      const aapat::LatticePoint q = L.slot(p, i);
      locations.push_back({q.x / 16.0f, q.y / 16.0f});
    }
  if (!g.sample_locations) {
    const bool same =
        L.grid_w == 1 && L.grid_h == 1 && L.positions[0] == standard_locations(L.sample_count);
    if (!same)
      throw NoDevice(
          fmt::format("{} has no VK_EXT_sample_locations, and these positions are not "
                      "the standard ones",
                      g.name));
  }
  const VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;

  // The multisampled colour image and the resolved storage image.
  auto ici = vk<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  ici.imageType = VK_IMAGE_TYPE_2D;
  ici.format = format;
  ici.extent = {static_cast<uint32_t>(w), static_cast<uint32_t>(h), 1};
  ici.mipLevels = 1;
  ici.arrayLayers = 1;
  ici.samples = samples;
  ici.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  VkImage msaa;
  check(vkCreateImage(g.device, &ici, nullptr, &msaa), "vkCreateImage (multisampled)");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(g.device, msaa, &req);
  VkDeviceMemory msaa_mem = bind_memory(g, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  vkBindImageMemory(g.device, msaa, msaa_mem, 0);
  ici.format = VK_FORMAT_R32_SFLOAT;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  VkImage resolved;
  check(vkCreateImage(g.device, &ici, nullptr, &resolved), "vkCreateImage (resolved)");
  vkGetImageMemoryRequirements(g.device, resolved, &req);
  VkDeviceMemory resolved_mem = bind_memory(g, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  vkBindImageMemory(g.device, resolved, resolved_mem, 0);
  auto view_of = [&](VkImage image, VkFormat f) {
    auto vci = vk<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    vci.image = image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = f;
    vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView v;
    check(vkCreateImageView(g.device, &vci, nullptr, &v), "vkCreateImageView");
    return v;
  };
  VkImageView msaa_view = view_of(msaa, format),
              resolved_view = view_of(resolved, VK_FORMAT_R32_SFLOAT);

  // Host-visible buffers: the vertices in, the resolved values out.
  const std::vector<Vertex> verts = triangles(scene, w, h);
  auto host_buffer = [&](VkDeviceSize size, VkBufferUsageFlags usage, VkBuffer& b) {
    auto bci = vk<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    bci.size = std::max<VkDeviceSize>(size, 16);
    bci.usage = usage;
    check(vkCreateBuffer(g.device, &bci, nullptr, &b), "vkCreateBuffer");
    VkMemoryRequirements r;
    vkGetBufferMemoryRequirements(g.device, b, &r);
    VkDeviceMemory m = bind_memory(
        g, r, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    vkBindBufferMemory(g.device, b, m, 0);
    return m;
  };
  VkBuffer vbuf, obuf;
  VkDeviceMemory vmem =
      host_buffer(verts.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vbuf);
  VkDeviceMemory omem = host_buffer(sizeof(float) * w * h, VK_BUFFER_USAGE_TRANSFER_DST_BIT, obuf);
  void* mapped;
  vkMapMemory(g.device, vmem, 0, VK_WHOLE_SIZE, 0, &mapped);
  if (!verts.empty()) std::memcpy(mapped, verts.data(), verts.size() * sizeof(Vertex));
  vkUnmapMemory(g.device, vmem);

  // Render pass: clear to the background, draw, leave the samples readable by a shader.
  VkAttachmentDescription att{};
  att.format = format;
  att.samples = samples;
  att.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  att.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  att.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  att.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  att.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  att.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription sub{};
  sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  sub.colorAttachmentCount = 1;
  sub.pColorAttachments = &ref;
  VkSubpassDependency dep{};
  dep.srcSubpass = 0;
  dep.dstSubpass = VK_SUBPASS_EXTERNAL;
  dep.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dep.dstStageMask = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
  dep.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dep.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
  auto rpci = vk<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
  rpci.attachmentCount = 1;
  rpci.pAttachments = &att;
  rpci.subpassCount = 1;
  rpci.pSubpasses = &sub;
  rpci.dependencyCount = 1;
  rpci.pDependencies = &dep;
  VkRenderPass pass;
  check(vkCreateRenderPass(g.device, &rpci, nullptr, &pass), "vkCreateRenderPass");
  auto fci = vk<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
  fci.renderPass = pass;
  fci.attachmentCount = 1;
  fci.pAttachments = &msaa_view;
  fci.width = w;
  fci.height = h;
  fci.layers = 1;
  VkFramebuffer fb;
  check(vkCreateFramebuffer(g.device, &fci, nullptr, &fb), "vkCreateFramebuffer");

  // The graphics pipeline, with the pattern's sample locations.
  auto plci = vk<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  VkPipelineLayout draw_layout;
  check(vkCreatePipelineLayout(g.device, &plci, nullptr, &draw_layout), "vkCreatePipelineLayout");
  VkShaderModule vs = shader_module(g, compile(kVertexShader, "vert")),
                 fs = shader_module(g, compile(kFragmentShader, "frag"));
  VkPipelineShaderStageCreateInfo stages[2] = {
      vk<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO),
      vk<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO)};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vs;
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fs;
  stages[1].pName = "main";
  VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription attrs[2] = {{0, 0, VK_FORMAT_R32G32_SFLOAT, 0},
                                                {1, 0, VK_FORMAT_R32_SFLOAT, 8}};
  auto vin = vk<VkPipelineVertexInputStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  vin.vertexBindingDescriptionCount = 1;
  vin.pVertexBindingDescriptions = &binding;
  vin.vertexAttributeDescriptionCount = 2;
  vin.pVertexAttributeDescriptions = attrs;
  auto ia = vk<VkPipelineInputAssemblyStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkViewport viewport{0, 0, static_cast<float>(w), static_cast<float>(h), 0, 1};
  VkRect2D scissor{{0, 0}, {static_cast<uint32_t>(w), static_cast<uint32_t>(h)}};
  auto vp =
      vk<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  vp.viewportCount = 1;
  vp.pViewports = &viewport;
  vp.scissorCount = 1;
  vp.pScissors = &scissor;
  auto rs = vk<VkPipelineRasterizationStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.cullMode = VK_CULL_MODE_NONE;
  rs.lineWidth = 1;
  auto sli = vk<VkSampleLocationsInfoEXT>(VK_STRUCTURE_TYPE_SAMPLE_LOCATIONS_INFO_EXT);
  sli.sampleLocationsPerPixel = samples;
  sli.sampleLocationGridSize = {static_cast<uint32_t>(L.grid_w), static_cast<uint32_t>(L.grid_h)};
  sli.sampleLocationsCount = static_cast<uint32_t>(locations.size());
  sli.pSampleLocations = locations.data();
  auto sls = vk<VkPipelineSampleLocationsStateCreateInfoEXT>(
      VK_STRUCTURE_TYPE_PIPELINE_SAMPLE_LOCATIONS_STATE_CREATE_INFO_EXT);
  sls.sampleLocationsEnable = VK_TRUE;
  sls.sampleLocationsInfo = sli;
  auto ms = vk<VkPipelineMultisampleStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  ms.rasterizationSamples = samples;
  ms.pNext = g.sample_locations ? &sls : nullptr;
  VkPipelineColorBlendAttachmentState blend{};
  blend.colorWriteMask = 0xf;
  auto cb = vk<VkPipelineColorBlendStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  cb.attachmentCount = 1;
  cb.pAttachments = &blend;
  auto gpci = vk<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  gpci.stageCount = 2;
  gpci.pStages = stages;
  gpci.pVertexInputState = &vin;
  gpci.pInputAssemblyState = &ia;
  gpci.pViewportState = &vp;
  gpci.pRasterizationState = &rs;
  gpci.pMultisampleState = &ms;
  gpci.pColorBlendState = &cb;
  gpci.layout = draw_layout;
  gpci.renderPass = pass;
  VkPipeline draw;
  check(vkCreateGraphicsPipelines(g.device, VK_NULL_HANDLE, 1, &gpci, nullptr, &draw),
        "vkCreateGraphicsPipelines");

  // The compute resolve: the export's GLSL, one invocation per output pixel.
  const std::string compute_source = fmt::format(
      "#version 450\nlayout(local_size_x = 8, local_size_y = 8) in;\n"
      "layout(binding = 0) uniform sampler2DMS aapat_src;\n"
      "layout(binding = 1, r32f) uniform writeonly image2D aapat_dst;\n{}\n"
      "void main() {{\n  ivec2 p = ivec2(gl_GlobalInvocationID.xy);\n"
      "  ivec2 size = textureSize(aapat_src);\n  if (p.x >= size.x || p.y >= size.y) return;\n"
      "  imageStore(aapat_dst, p, vec4(aapat_resolve(aapat_src, p).r));\n}}\n",
      glsl);
  VkDescriptorSetLayoutBinding b[2] = {
      {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
  auto dslci =
      vk<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  dslci.bindingCount = 2;
  dslci.pBindings = b;
  VkDescriptorSetLayout dsl;
  check(vkCreateDescriptorSetLayout(g.device, &dslci, nullptr, &dsl),
        "vkCreateDescriptorSetLayout");
  plci.setLayoutCount = 1;
  plci.pSetLayouts = &dsl;
  VkPipelineLayout compute_layout;
  check(vkCreatePipelineLayout(g.device, &plci, nullptr, &compute_layout),
        "vkCreatePipelineLayout");
  VkShaderModule cs = shader_module(g, compile(compute_source, "comp"));
  auto cpci = vk<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
  cpci.stage =
      vk<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
  cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  cpci.stage.module = cs;
  cpci.stage.pName = "main";
  cpci.layout = compute_layout;
  VkPipeline resolve;
  check(vkCreateComputePipelines(g.device, VK_NULL_HANDLE, 1, &cpci, nullptr, &resolve),
        "vkCreateComputePipelines");
  auto sci = vk<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  VkSampler sampler;
  check(vkCreateSampler(g.device, &sci, nullptr, &sampler), "vkCreateSampler");
  VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
  auto dpci = vk<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  dpci.maxSets = 1;
  dpci.poolSizeCount = 2;
  dpci.pPoolSizes = sizes;
  VkDescriptorPool pool;
  check(vkCreateDescriptorPool(g.device, &dpci, nullptr, &pool), "vkCreateDescriptorPool");
  auto dsai = vk<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  dsai.descriptorPool = pool;
  dsai.descriptorSetCount = 1;
  dsai.pSetLayouts = &dsl;
  VkDescriptorSet set;
  check(vkAllocateDescriptorSets(g.device, &dsai, &set), "vkAllocateDescriptorSets");
  VkDescriptorImageInfo src_info{sampler, msaa_view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkDescriptorImageInfo dst_info{VK_NULL_HANDLE, resolved_view, VK_IMAGE_LAYOUT_GENERAL};
  VkWriteDescriptorSet writes[2] = {
      vk<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET),
      vk<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET)};
  writes[0].dstSet = set;
  writes[0].dstBinding = 0;
  writes[0].descriptorCount = 1;
  writes[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  writes[0].pImageInfo = &src_info;
  writes[1] = writes[0];
  writes[1].dstBinding = 1;
  writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  writes[1].pImageInfo = &dst_info;
  vkUpdateDescriptorSets(g.device, 2, writes, 0, nullptr);

  // Record: draw, resolve, copy out.
  auto cpi = vk<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  cpi.queueFamilyIndex = g.family;
  VkCommandPool cmd_pool;
  check(vkCreateCommandPool(g.device, &cpi, nullptr, &cmd_pool), "vkCreateCommandPool");
  auto cbai = vk<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  cbai.commandPool = cmd_pool;
  cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cbai.commandBufferCount = 1;
  VkCommandBuffer cmd;
  check(vkAllocateCommandBuffers(g.device, &cbai, &cmd), "vkAllocateCommandBuffers");
  auto begin = vk<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  vkBeginCommandBuffer(cmd, &begin);
  const float bg = static_cast<float>(scene.background);
  VkClearValue clear{};
  clear.color = {{bg, bg, bg, 1}};
  auto rpbi = vk<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
  rpbi.renderPass = pass;
  rpbi.framebuffer = fb;
  rpbi.renderArea = scissor;
  rpbi.clearValueCount = 1;
  rpbi.pClearValues = &clear;
  vkCmdBeginRenderPass(cmd, &rpbi, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw);
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vbuf, &zero);
  vkCmdDraw(cmd, static_cast<uint32_t>(verts.size()), 1, 0, 0);
  vkCmdEndRenderPass(cmd);
  auto to_general = vk<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
  to_general.srcAccessMask = 0;
  to_general.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  to_general.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  to_general.newLayout = VK_IMAGE_LAYOUT_GENERAL;
  to_general.srcQueueFamilyIndex = to_general.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_general.image = resolved;
  to_general.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       0, 0, nullptr, 0, nullptr, 1, &to_general);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resolve);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_layout, 0, 1, &set, 0,
                          nullptr);
  vkCmdDispatch(cmd, (w + 7) / 8, (h + 7) / 8, 1);
  VkImageMemoryBarrier to_copy = to_general;
  to_copy.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  to_copy.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  to_copy.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
  to_copy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                       0, nullptr, 0, nullptr, 1, &to_copy);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {static_cast<uint32_t>(w), static_cast<uint32_t>(h), 1};
  vkCmdCopyImageToBuffer(cmd, resolved, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, obuf, 1, &region);
  auto to_host = vk<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &to_host, 0, nullptr, 0, nullptr);
  vkEndCommandBuffer(cmd);
  auto submit = vk<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  check(vkQueueSubmit(g.queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  check(vkQueueWaitIdle(g.queue), "vkQueueWaitIdle");
  std::vector<float> values(static_cast<size_t>(w) * h);
  vkMapMemory(g.device, omem, 0, VK_WHOLE_SIZE, 0, &mapped);
  std::memcpy(values.data(), mapped, values.size() * sizeof(float));
  vkUnmapMemory(g.device, omem);
  // The device is destroyed with everything on it when the program ends; a
  // one-shot tool need not release each object.
  return values;
}

int run(int argc, char** argv) {
  CLI::App app{"render a scene on a GPU with an exported pattern and compare with aapat render"};
  std::string export_path, scene_path, size = "64x64", gpu_png, cpu_png;
  int expect = -1;
  app.add_option("export", export_path, "aapat export ... --api vulkan output")->required();
  app.add_option("scene", scene_path, "scene file of convex polygons (.json)")->required();
  app.add_option("--size", size, "WIDTHxHEIGHT (multiples of the grid)")->capture_default_str();
  app.add_option("--gpu", gpu_png, "write the GPU's image (.png)");
  app.add_option("--cpu", cpu_png, "write aapat render's image (.png)");
  app.add_option("--expect-max-deviation", expect,
                 "fail (exit 2) if the largest deviation on the 0-255 scale is above this");
  CLI11_PARSE(app, argc, argv);
  try {
    const auto [w, h] = aapat::parse_size(size, "--size", 4096);
    const std::string text = aapat::read_file(export_path, "export");
    const aapat::HardwareLayout L = aapat::parse_export(text, export_path);
    if (L.profile != "vulkan") throw Error("export with --api vulkan");
    if (w < 16 || h < 16 || w > 4096 || h > 4096 || w % L.grid_w || h % L.grid_h)
      throw Error(fmt::format("--size {}: 16 to 4096, multiples of the {}x{} grid", size, L.grid_w,
                              L.grid_h));
    const aapat::ShapesScene scene =
        aapat::scene_from_json(aapat::read_file(scene_path, "scene"), scene_path);
    Gpu gpu;
    open_gpu(gpu);
    const std::vector<float> gpu_values = render_on_gpu(gpu, L, resolve_glsl(text), scene, w, h);

    aapat::Sampling sampling;
    sampling.pattern = aapat::pattern_from_layout(L);
    const aapat::Image cpu = aapat::render(scene, w, h, sampling, std::nullopt);
    // Compare inside a one-pixel margin: at the image's edge the GPU resolve clamps.
    aapat::Image a{w - 2, h - 2, 0, {}}, b{w - 2, h - 2, 0, {}};
    for (int j = 1; j < h - 1; ++j)
      for (int i = 1; i < w - 1; ++i) {
        a.values.push_back(gpu_values[static_cast<size_t>(h - 1 - j) * w + i]);
        b.values.push_back(cpu.at(i, j));
      }
    const aapat::ImageError e = aapat::compare(a, b);
    double largest = 0;
    for (size_t k = 0; k < a.values.size(); ++k)
      largest = std::max(largest, std::abs(a.values[k] - b.values[k]));
    fmt::print("{} on {} ({}): {}x{}, {}x MSAA, {}x{} grid\n", L.name, gpu.name,
               gpu.sample_locations ? "VK_EXT_sample_locations" : "standard sample locations", w, h,
               L.sample_count, L.grid_w, L.grid_h);
    fmt::print(
        "GPU against aapat render, inside a 1-pixel margin: RMSE {:.4f}, max deviation {} "
        "(0-255), largest difference {:.6f}\n",
        e.rmse, e.max_deviation, largest);
    std::vector<uint8_t> px(static_cast<size_t>(w) * h);
    for (size_t k = 0; k < px.size(); ++k)
      px[k] = static_cast<uint8_t>(std::lround(255 * std::clamp(double(gpu_values[k]), 0.0, 1.0)));
    if (!gpu_png.empty()) aapat::write_png_gray(gpu_png, w, h, px);
    if (!cpu_png.empty()) aapat::write_png_gray(cpu_png, w, h, aapat::level_pixels(cpu));
    if (expect >= 0 && e.max_deviation > expect) {
      fmt::print(stderr, "aapat-vk-compare: max deviation {} is above the expected {}\n",
                 e.max_deviation, expect);
      return 2;
    }
    return 0;
  } catch (const NoDevice& e) {
    fmt::print(stderr, "aapat-vk-compare: skipped: {}\n", e.what());
    return kNoDevice;
  } catch (const std::exception& e) {
    fmt::print(stderr, "aapat-vk-compare: error: {}\n", e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  return run(argc, argv);
}
