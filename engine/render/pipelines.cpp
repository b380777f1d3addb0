#include "engine/render/pipelines.h"

#include <cstddef>
#include <cstdint>
#include <vector>
#include "engine/render/frame.h"
#include "fullscreen_vert.h"
#include "sky_frag.h"
#include "ground_vert.h"
#include "ground_frag.h"
#include "mesh_vert.h"
#include "mesh_frag.h"
#include "shadow_vert.h"
#include "line_vert.h"
#include "point_vert.h"
#include "debug_frag.h"

namespace eng::render {
namespace {

eng::Result<VkRenderPass> make_shadow_pass(VkDevice dev) {
  VkAttachmentDescription d{};
  d.format = kShadowFormat;
  d.samples = VK_SAMPLE_COUNT_1_BIT;
  d.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  d.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  d.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  d.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  d.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  d.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription sub{};
  sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  sub.pDepthStencilAttachment = &ref;
  // In: last frame's fragment shader reads must finish before we overwrite. Out: depth writes visible to sampling.
  VkSubpassDependency deps[2]{};
  deps[0] = {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
             VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, 0,
             VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT, 0};
  deps[1] = {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
             VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, 0};
  VkRenderPassCreateInfo ci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  ci.attachmentCount = 1;
  ci.pAttachments = &d;
  ci.subpassCount = 1;
  ci.pSubpasses = &sub;
  ci.dependencyCount = 2;
  ci.pDependencies = deps;
  VkRenderPass rp = VK_NULL_HANDLE;
  ENG_VK_TRY(vkCreateRenderPass(dev, &ci, nullptr, &rp), "vkCreateRenderPass(shadow)");
  return rp;
}

eng::Result<VkRenderPass> make_scene_pass(VkDevice dev, VkSampleCountFlagBits samples) {
  const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
  VkAttachmentDescription a[3]{};
  a[0].format = kColorFormat;
  a[0].samples = samples;
  a[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a[0].storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
  a[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  a[0].finalLayout = msaa ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  a[1] = a[0];
  a[1].format = kDepthFormat;
  a[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  a[2] = a[0];
  a[2].samples = VK_SAMPLE_COUNT_1_BIT;
  a[2].loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a[2].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a[2].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkAttachmentReference resolve{2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription sub{};
  sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  sub.colorAttachmentCount = 1;
  sub.pColorAttachments = &color;
  sub.pDepthStencilAttachment = &depth;
  if (msaa) sub.pResolveAttachments = &resolve;
  // In: the previous frame's copies/blits out of the resolved image and its attachment writes must be done.
  // Out: resolved colour visible to the overlay pass and to transfers (readback, blit to the swapchain).
  VkSubpassDependency deps[2]{};
  deps[0] = {VK_SUBPASS_EXTERNAL, 0,
             VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
             VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
             VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
             VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                 VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
             0};
  deps[1] = {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
             VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
             VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
             VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, 0};
  VkRenderPassCreateInfo ci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  ci.attachmentCount = msaa ? 3 : 2;
  ci.pAttachments = a;
  ci.subpassCount = 1;
  ci.pSubpasses = &sub;
  ci.dependencyCount = 2;
  ci.pDependencies = deps;
  VkRenderPass rp = VK_NULL_HANDLE;
  ENG_VK_TRY(vkCreateRenderPass(dev, &ci, nullptr, &rp), "vkCreateRenderPass(scene)");
  return rp;
}

eng::Result<VkRenderPass> make_overlay_pass(VkDevice dev) {
  VkAttachmentDescription a{};
  a.format = kColorFormat;
  a.samples = VK_SAMPLE_COUNT_1_BIT;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  a.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription sub{};
  sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  sub.colorAttachmentCount = 1;
  sub.pColorAttachments = &ref;
  VkSubpassDependency deps[2]{};
  deps[0] = {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
             VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
             VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, 0};
  deps[1] = {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
             VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, 0};
  VkRenderPassCreateInfo ci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  ci.attachmentCount = 1;
  ci.pAttachments = &a;
  ci.subpassCount = 1;
  ci.pSubpasses = &sub;
  ci.dependencyCount = 2;
  ci.pDependencies = deps;
  VkRenderPass rp = VK_NULL_HANDLE;
  ENG_VK_TRY(vkCreateRenderPass(dev, &ci, nullptr, &rp), "vkCreateRenderPass(overlay)");
  return rp;
}

enum class Input { None, Mesh, MeshPositionOnly, Line, Point };

struct PipelineDesc {
  const uint32_t* vs;
  size_t vs_bytes;
  const uint32_t* fs = nullptr;
  size_t fs_bytes = 0;
  Input input = Input::None;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  bool depth_test = true, depth_write = true, blend = false, depth_bias = false, shadow = false;
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS_OR_EQUAL;
  int fragment_variant = -1;  // >= 0: the fragment shader's specialization constant 0 (ground.frag: GroundVariant)
};

eng::Result<VkPipeline> make_pipeline(const VkContext& ctx, const Pipelines& p, VkSampleCountFlagBits samples,
                                      const PipelineDesc& d) {
  auto vs = ctx.shader(d.vs, d.vs_bytes);
  if (!vs) return eng::make_error(vs.error());
  VkShaderModule fs = VK_NULL_HANDLE;
  if (d.fs) {
    auto f = ctx.shader(d.fs, d.fs_bytes);
    if (!f) {
      vkDestroyShaderModule(ctx.device, *vs, nullptr);
      return eng::make_error(f.error());
    }
    fs = *f;
  }
  VkPipelineShaderStageCreateInfo stages[2]{};
  stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, *vs, "main", nullptr};
  stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT, fs, "main", nullptr};
  // A specialization constant, not a uniform: the driver folds it and drops the branch it rules out (a CPU
  // rasteriser runs both sides of a uniform branch under a mask, so only a folded branch saves work).
  const int32_t variant = d.fragment_variant;
  const VkSpecializationMapEntry entry{0, 0, sizeof(int32_t)};
  const VkSpecializationInfo spec{1, &entry, sizeof(int32_t), &variant};
  if (d.fragment_variant >= 0) stages[1].pSpecializationInfo = &spec;

  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attrs;
  switch (d.input) {
    case Input::None: break;
    case Input::Mesh:
    case Input::MeshPositionOnly:
      bindings.push_back({0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX});
      attrs.push_back({0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)});
      if (d.input == Input::Mesh) attrs.push_back({1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)});
      break;
    case Input::Line:
      bindings.push_back({0, sizeof(DebugVertex), VK_VERTEX_INPUT_RATE_VERTEX});
      attrs.push_back({0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(DebugVertex, pos)});
      attrs.push_back({1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(DebugVertex, color)});
      break;
    case Input::Point:
      // One record per point, stepped per instance; the six quad corners come from gl_VertexIndex.
      bindings.push_back({0, sizeof(DebugPoint), VK_VERTEX_INPUT_RATE_INSTANCE});
      attrs.push_back({0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(DebugPoint, p)});
      attrs.push_back({1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(DebugPoint, color)});
      break;
  }
  VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vi.vertexBindingDescriptionCount = static_cast<uint32_t>(bindings.size());
  vi.pVertexBindingDescriptions = bindings.data();
  vi.vertexAttributeDescriptionCount = static_cast<uint32_t>(attrs.size());
  vi.pVertexAttributeDescriptions = attrs.data();
  VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  ia.topology = d.topology;
  VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  vp.viewportCount = 1;
  vp.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.cullMode = d.cull;
  // Meshes wind counter-clockwise seen from outside. The camera's Y-flipped projection and Vulkan's Y-down
  // framebuffer cancel out, so CCW stays front-facing.
  rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  rs.lineWidth = 1.0f;
  rs.depthBiasEnable = d.depth_bias ? VK_TRUE : VK_FALSE;
  // Slope-scaled bias removes acne on surfaces grazing the sun; the constant part covers flat-on surfaces.
  rs.depthBiasConstantFactor = 1.5f;
  rs.depthBiasSlopeFactor = 2.0f;
  VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  ms.rasterizationSamples = d.shadow ? VK_SAMPLE_COUNT_1_BIT : samples;
  VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  ds.depthTestEnable = d.depth_test ? VK_TRUE : VK_FALSE;
  ds.depthWriteEnable = d.depth_write ? VK_TRUE : VK_FALSE;
  ds.depthCompareOp = d.depth_compare;
  VkPipelineColorBlendAttachmentState cb{};
  cb.colorWriteMask = 0xF;
  if (d.blend) {
    cb.blendEnable = VK_TRUE;
    cb.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    cb.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    cb.colorBlendOp = VK_BLEND_OP_ADD;
    // Keep destination alpha (1): frames stay opaque for screenshots.
    cb.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
    cb.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    cb.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  VkPipelineColorBlendStateCreateInfo cbs{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  cbs.attachmentCount = d.shadow ? 0 : 1;
  cbs.pAttachments = &cb;
  VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dy.dynamicStateCount = 2;
  dy.pDynamicStates = dyn;
  VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  ci.stageCount = d.fs ? 2 : 1;
  ci.pStages = stages;
  ci.pVertexInputState = &vi;
  ci.pInputAssemblyState = &ia;
  ci.pViewportState = &vp;
  ci.pRasterizationState = &rs;
  ci.pMultisampleState = &ms;
  ci.pDepthStencilState = &ds;
  ci.pColorBlendState = &cbs;
  ci.pDynamicState = &dy;
  ci.layout = p.layout;
  ci.renderPass = d.shadow ? p.shadow_pass : p.scene_pass;
  VkPipeline pipe = VK_NULL_HANDLE;
  const VkResult r = vkCreateGraphicsPipelines(ctx.device, VK_NULL_HANDLE, 1, &ci, nullptr, &pipe);
  vkDestroyShaderModule(ctx.device, *vs, nullptr);
  if (fs) vkDestroyShaderModule(ctx.device, fs, nullptr);
  ENG_VK_TRY(r, "vkCreateGraphicsPipelines");
  return pipe;
}

}  // namespace

eng::Result<void> create_pipelines(const VkContext& ctx, VkSampleCountFlagBits samples, Pipelines& p) {
  auto sp = make_shadow_pass(ctx.device);
  if (!sp) return eng::make_error(sp.error());
  p.shadow_pass = *sp;
  auto sc = make_scene_pass(ctx.device, samples);
  if (!sc) return eng::make_error(sc.error());
  p.scene_pass = *sc;
  auto op = make_overlay_pass(ctx.device);
  if (!op) return eng::make_error(op.error());
  p.overlay_pass = *op;

  VkDescriptorSetLayoutBinding b[3]{};
  b[0] = {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  b[1] = {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  b[2] = {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  lci.bindingCount = 3;
  lci.pBindings = b;
  ENG_VK_TRY(vkCreateDescriptorSetLayout(ctx.device, &lci, nullptr, &p.set_layout), "vkCreateDescriptorSetLayout");
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = 1;
  plci.pSetLayouts = &p.set_layout;
  ENG_VK_TRY(vkCreatePipelineLayout(ctx.device, &plci, nullptr, &p.layout), "vkCreatePipelineLayout");

  struct Job {
    VkPipeline* out;
    PipelineDesc d;
  };
  PipelineDesc shadow{shadow_vert, sizeof(shadow_vert)};
  shadow.input = Input::MeshPositionOnly;
  shadow.depth_bias = true;
  shadow.shadow = true;
  // The sky is drawn last, at the far plane, only where nothing else drew (depth still cleared to 1).
  PipelineDesc sky{fullscreen_vert, sizeof(fullscreen_vert), sky_frag, sizeof(sky_frag)};
  sky.depth_write = false;
  // The ground is drawn after the opaque bodies (depth-tested fragments behind them are never shaded), LESS so
  // a body touching the ground keeps its pixels as when the ground came first. Two variants (ground.frag): the
  // shadow map's footprint with shadows, then the rest without.
  PipelineDesc ground{ground_vert, sizeof(ground_vert), ground_frag, sizeof(ground_frag)};
  ground.depth_compare = VK_COMPARE_OP_LESS;
  PipelineDesc ground_shadowed = ground;
  ground_shadowed.fragment_variant = 0;
  ground.fragment_variant = 1;
  PipelineDesc opaque{mesh_vert, sizeof(mesh_vert), mesh_frag, sizeof(mesh_frag)};
  opaque.input = Input::Mesh;
  opaque.cull = VK_CULL_MODE_BACK_BIT;
  PipelineDesc ghost = opaque;
  ghost.depth_write = false;
  ghost.blend = true;
  PipelineDesc lines{line_vert, sizeof(line_vert), debug_frag, sizeof(debug_frag)};
  lines.input = Input::Line;
  lines.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
  lines.depth_write = false;
  lines.blend = true;
  PipelineDesc points{point_vert, sizeof(point_vert), debug_frag, sizeof(debug_frag)};
  points.input = Input::Point;
  points.depth_write = false;
  points.blend = true;
  PipelineDesc lines_on_top = lines, points_on_top = points;
  lines_on_top.depth_test = points_on_top.depth_test = false;
  const Job jobs[] = {{&p.shadow, shadow}, {&p.sky, sky},     {&p.ground, ground}, {&p.ground_shadowed, ground_shadowed}, {&p.opaque, opaque},
                      {&p.ghost, ghost},   {&p.lines, lines}, {&p.points, points}, {&p.lines_on_top, lines_on_top},
                      {&p.points_on_top, points_on_top}};
  for (const Job& j : jobs) {
    auto r = make_pipeline(ctx, p, samples, j.d);
    if (!r) return eng::make_error(r.error());
    *j.out = *r;
  }
  return {};
}

void destroy_pipelines(const VkContext& ctx, Pipelines& p) {
  for (VkPipeline pipe : {p.shadow, p.sky, p.ground, p.ground_shadowed, p.opaque, p.ghost, p.lines, p.points, p.lines_on_top, p.points_on_top})
    if (pipe) vkDestroyPipeline(ctx.device, pipe, nullptr);
  if (p.layout) vkDestroyPipelineLayout(ctx.device, p.layout, nullptr);
  if (p.set_layout) vkDestroyDescriptorSetLayout(ctx.device, p.set_layout, nullptr);
  for (VkRenderPass rp : {p.shadow_pass, p.scene_pass, p.overlay_pass})
    if (rp) vkDestroyRenderPass(ctx.device, rp, nullptr);
  p = Pipelines{};
}

}  // namespace eng::render
