"""Projects as Python data: a project document (dict) with the folder its relative paths are
resolved against, and JSON pointers into it (RFC 6901)."""
import copy
import json
import os

from . import _luxgrid


class Project:
    """A project document and the folder its relative photometry paths are resolved against.

    document: the project as a dict (as the project file holds it); base_dir: an absolute path;
    name: how messages name it (the file's name, or "<dict>"); path: the file it was loaded
    from, or None; warnings: the loader's warnings (legal but suspicious input).
    """

    def __init__(self, document, base_dir=None, name="<dict>", path=None, warnings=()):
        if not isinstance(document, dict):
            raise TypeError("a project document is a dict, got " + type(document).__name__)
        self.document = document
        # Resolved now: the folder must stay the same wherever (and on whichever Dask worker) the
        # project is calculated later.
        self.base_dir = os.path.abspath(os.fspath(base_dir) if base_dir is not None else ".")
        self.name = name
        self.path = path
        self.warnings = list(warnings)

    @classmethod
    def of(cls, project, base_dir=None):
        """A Project from a Project, a dict or a path (loaded: load())."""
        if isinstance(project, Project):
            if base_dir is not None:
                raise TypeError("base_dir applies to a project given as a dict")
            return project
        if isinstance(project, dict):
            return cls(project, base_dir)
        if isinstance(project, (str, os.PathLike)):
            if base_dir is not None:
                raise TypeError("base_dir applies to a project given as a dict, not to a file")
            return load(project)
        raise TypeError("a project is a path, a dict or a luxgrid.Project, got " +
                        type(project).__name__)

    def source(self):
        """(text, name, base_dir) as the loader takes them."""
        return json.dumps(self.document, allow_nan=False), self.name, self.base_dir

    def get(self, pointer):
        """The value at a JSON pointer; PointerError (a KeyError) where there is none."""
        return resolve(self.document, pointer)

    def with_values(self, values):
        """A copy with each {pointer: value} set; every pointer must exist (PointerError)."""
        document = copy.deepcopy(self.document)
        for pointer, value in values.items():
            assign(document, pointer, copy.deepcopy(value))
        return Project(document, self.base_dir, self.name, self.path)

    def __repr__(self):
        return f"<luxgrid.Project {self.name!r} in {self.base_dir!r}>"


def load(path):
    """Load a project file as `luxgrid calc` does and return it as a Project (its document, its
    folder as base_dir, its warnings). Bad input raises InputError with its place."""
    path = os.fspath(path)
    document, warnings = _luxgrid.read_project(path)
    return Project(document, os.path.dirname(os.path.abspath(path)), os.path.basename(path),
                   path, warnings)


class PointerError(KeyError):
    """A JSON pointer that names no value of the project: .pointer is it."""

    def __init__(self, pointer, message):
        super().__init__(f"{pointer}: {message}")
        self.pointer = pointer


def _tokens(pointer):
    if not isinstance(pointer, str) or (pointer and not pointer.startswith("/")):
        raise PointerError(pointer, "a JSON pointer starts with '/'")
    if pointer == "":
        return []
    return [t.replace("~1", "/").replace("~0", "~") for t in pointer[1:].split("/")]


def _step(value, token, pointer):
    if isinstance(value, dict):
        if token in value:
            return token
    elif isinstance(value, list):
        if token.isdigit() and (token == "0" or not token.startswith("0")) and \
                int(token) < len(value):
            return int(token)
    raise PointerError(pointer, "no such value in the project")


def resolve(document, pointer):
    """The value at `pointer` in `document`; PointerError where there is none."""
    value = document
    for token in _tokens(pointer):
        value = value[_step(value, token, pointer)]
    return value


def assign(document, pointer, new_value):
    """Replaces the value at `pointer` (which must exist) by `new_value`."""
    tokens = _tokens(pointer)
    if not tokens:
        raise PointerError(pointer, "a variant cannot replace the whole project")
    parent = document
    for token in tokens[:-1]:
        parent = parent[_step(parent, token, pointer)]
    parent[_step(parent, tokens[-1], pointer)] = new_value
