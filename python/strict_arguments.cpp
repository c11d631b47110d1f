// Every bad argument is aapat.Error, its type included. pybind11 raises
// TypeError ("incompatible function arguments") from its dispatcher, before
// any of the module's code runs, so each function, method and constructor is
// wrapped once, at import, to raise aapat.Error with the same message (it
// names the signatures taken). aapat.Error derives from both ValueError and
// TypeError, so `except TypeError` and `except ValueError` still catch what
// they caught. The wrappers keep the name, the docstring (its first line is
// the signature) and __wrapped__.
#include <pybind11/eval.h>

#include "bindings.h"

namespace aapat::python {

namespace {

constexpr const char* kWrapper = R"py(
import functools

def _incompatible(error):
    text = str(error)
    return ("incompatible function arguments" in text
            or "incompatible constructor arguments" in text)

def _strict(f, Error):
    @functools.wraps(f)
    def call(*args, **kwargs):
        try:
            return f(*args, **kwargs)
        except TypeError as e:
            if isinstance(e, Error) or not _incompatible(e):
                raise
            raise Error(str(e)) from None
    return call

def _strict_module(module, Error):
    pybind_function = type(module.registry)
    for name, value in list(vars(module).items()):
        if isinstance(value, pybind_function):
            setattr(module, name, _strict(value, Error))
        elif isinstance(value, type) and value.__module__ == module.__name__ \
                and not issubclass(value, BaseException):
            for attr, member in list(vars(value).items()):
                if attr in ("__init__", "__call__") or (not attr.startswith("__")
                                                         and callable(member)):
                    wrapped = _strict(member, Error)
                    if isinstance(member, staticmethod):
                        wrapped = staticmethod(_strict(member.__func__, Error))
                    setattr(value, attr, wrapped)
)py";

}  // namespace

void strict_arguments(py::module_& m) {
  py::dict scope;
  scope["__builtins__"] = py::module_::import("builtins");
  py::exec(kWrapper, scope);
  scope["_strict_module"](m, m.attr("Error"));
}

}  // namespace aapat::python
