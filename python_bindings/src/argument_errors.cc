// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include <pybind11/eval.h>

#include "bindings.h"

namespace isovdb::python {

// Wrong arguments, in Python terms. Two messages fall short otherwise: Python's own for an
// unknown keyword names it but not the keywords there are, and pybind11's "incompatible
// function arguments" prints every argument's repr (a numpy volume in full) and never
// says which keyword was unknown. Each public function is wrapped (functools.wraps: its
// name, docstring and signature stay, and pickling finds it by its name); the
// wrapper checks the keywords against the function's, then calls it. The accepted names
// come from inspect.signature, or for a pybind11 function from the signature line that
// starts its docstring.
void nameWrongArguments(py::module_& m) {
  py::exec(R"py(
def _name_wrong_arguments(module):
    import difflib, functools, inspect

    def signature_line(function):
        return ((function.__doc__ or "").splitlines() or [""])[0]

    def keywords_of(function):
        """The keywords a function takes, or None when it takes any (**kwargs, overloads)."""
        try:
            parameters = inspect.signature(function).parameters.values()
            if any(p.kind == p.VAR_KEYWORD for p in parameters):
                return None
            return [p.name for p in parameters if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)]
        except (TypeError, ValueError):
            pass
        line = signature_line(function)
        start, end = line.find("("), line.rfind(")")
        if start < 0 or end < start or "**" in line:
            return None
        names, depth, piece = [], 0, ""
        for c in line[start + 1:end] + ",":
            if c in "[(":
                depth += 1
            elif c in "])":
                depth -= 1
            if c == "," and depth == 0:
                name = piece.split(":")[0].split("=")[0].strip()
                if name not in ("", "*", "/"):
                    names.append(name)
                piece = ""
            else:
                piece += c
        return names

    def type_name(value):
        kind = type(value)
        return kind.__qualname__ if kind.__module__ == "builtins" else f"{kind.__module__}.{kind.__qualname__}"

    def guarded(name, function):
        keywords = keywords_of(function)

        @functools.wraps(function)
        def call(*args, **kwargs):
            for keyword in kwargs if keywords is not None else ():
                if keyword not in keywords:
                    close = difflib.get_close_matches(keyword, keywords, n=1)
                    hint = f" (did you mean {close[0]!r}?)" if close else ""
                    raise TypeError(f"{name}() got an unexpected keyword argument {keyword!r}{hint}; "
                                    f"its keywords are: {', '.join(keywords)}") from None
            try:
                return function(*args, **kwargs)
            except TypeError as error:
                if not str(error).startswith(f"{name}(): incompatible function arguments"):
                    raise
                given = [type_name(a) for a in args] + [f"{k}={type_name(v)}" for k, v in kwargs.items()]
                raise TypeError(f"{name}(): an argument has the wrong type: called with ({', '.join(given)}); "
                                f"it takes {signature_line(function)}") from None
        # pybind11's functions are "PyCapsule.<name>": found by their own name, they pickle.
        call.__qualname__, call.__module__ = name, module.__name__
        return call

    for name in [n for n in dir(module) if not n.startswith("_")]:
        function = getattr(module, name)
        if callable(function) and not isinstance(function, type):
            setattr(module, name, guarded(name, function))
)py",
           m.attr("__dict__"));
  m.attr("_name_wrong_arguments")(m);
  py::delattr(m, "_name_wrong_arguments");
}

}  // namespace isovdb::python
