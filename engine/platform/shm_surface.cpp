#include "engine/platform/shm_surface.h"

#include <sys/ipc.h>
#include <sys/shm.h>

#include "engine/platform/window.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>

namespace eng::platform {

struct ShmSurface::Impl {
  Display* display = nullptr;
  ::Window window = 0;
  GC gc = nullptr;
  XImage* image = nullptr;
  XShmSegmentInfo segment{};
  bool attached = false;

  ~Impl() {
    if (attached) {
      XShmDetach(display, &segment);
      XSync(display, False);
    }
    if (image) XDestroyImage(image);  // frees the XImage struct only: its data is the segment (set to null below)
    if (segment.shmaddr && segment.shmaddr != reinterpret_cast<char*>(-1)) shmdt(segment.shmaddr);
    if (gc) XFreeGC(display, gc);
  }
};

namespace {
// XShmAttach reports failure (a remote server, a container without a shared IPC namespace) as an asynchronous X
// error, which by default ends the process: caught while attaching.
bool g_attach_failed = false;
int on_attach_error(Display*, XErrorEvent*) {
  g_attach_failed = true;
  return 0;
}
}  // namespace

eng::Result<std::unique_ptr<ShmSurface>> ShmSurface::create(const Window& window, int width, int height) {
  if (width <= 0 || height <= 0) return eng::make_error("shared-memory surface: size must be positive");
  auto im = std::make_unique<Impl>();
  im->display = glfwGetX11Display();
  im->window = glfwGetX11Window(window.handle());
  if (!im->display || !im->window) return eng::make_error("shared-memory surface: the window is not an X11 window");
  if (!XShmQueryExtension(im->display)) return eng::make_error("shared-memory surface: the X server has no MIT-SHM");
  XWindowAttributes wa;
  if (!XGetWindowAttributes(im->display, im->window, &wa)) return eng::make_error("shared-memory surface: no window attributes");
  const Visual* v = wa.visual;
  if ((wa.depth != 24 && wa.depth != 32) || v->red_mask != 0xff0000 || v->green_mask != 0xff00 || v->blue_mask != 0xff)
    return eng::make_error("shared-memory surface: the window's visual is not 24-bit BGRX true colour");
  im->image = XShmCreateImage(im->display, wa.visual, static_cast<unsigned>(wa.depth), ZPixmap, nullptr, &im->segment,
                              static_cast<unsigned>(width), static_cast<unsigned>(height));
  if (!im->image || im->image->bits_per_pixel != 32 || im->image->byte_order != LSBFirst)
    return eng::make_error("shared-memory surface: the server's image format is not 32-bit little-endian");
  const size_t bytes = static_cast<size_t>(im->image->bytes_per_line) * static_cast<size_t>(height);
  im->segment.shmid = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0600);
  if (im->segment.shmid < 0) return eng::make_error("shared-memory surface: shmget failed");
  im->segment.shmaddr = static_cast<char*>(shmat(im->segment.shmid, nullptr, 0));
  if (im->segment.shmaddr == reinterpret_cast<char*>(-1)) {
    shmctl(im->segment.shmid, IPC_RMID, nullptr);
    return eng::make_error("shared-memory surface: shmat failed");
  }
  im->image->data = im->segment.shmaddr;
  im->segment.readOnly = False;
  g_attach_failed = false;
  XSync(im->display, False);
  auto* previous = XSetErrorHandler(on_attach_error);
  const bool sent = XShmAttach(im->display, &im->segment);
  XSync(im->display, False);
  XSetErrorHandler(previous);
  // Marked for removal now: the segment lives while attached and mapped, and goes away even if the process dies.
  shmctl(im->segment.shmid, IPC_RMID, nullptr);
  if (!sent || g_attach_failed) {
    im->image->data = nullptr;
    return eng::make_error("shared-memory surface: the X server could not attach the segment (not a local display?)");
  }
  im->attached = true;
  im->gc = XCreateGC(im->display, im->window, 0, nullptr);
  return std::unique_ptr<ShmSurface>(new ShmSurface(std::move(im), width, height));
}

ShmSurface::ShmSurface(std::unique_ptr<Impl> impl, int width, int height)
    : impl_(std::move(impl)), width_(width), height_(height) {}

ShmSurface::~ShmSurface() {
  if (impl_ && impl_->image) impl_->image->data = nullptr;  // the segment is not XDestroyImage's to free
}

uint8_t* ShmSurface::pixels() { return reinterpret_cast<uint8_t*>(impl_->segment.shmaddr); }
int ShmSurface::stride() const { return impl_->image->bytes_per_line; }

void ShmSurface::present() {
  XShmPutImage(impl_->display, impl_->window, impl_->gc, impl_->image, 0, 0, 0, 0, static_cast<unsigned>(width_),
               static_cast<unsigned>(height_), False);
  // A round trip: the server has copied the segment once it answers, so the next frame may overwrite it.
  XSync(impl_->display, False);
}

}  // namespace eng::platform
