"""The wear laws by name (:data:`LAWS`, the choices of the case key ``wear.law``): each declared by its own module
of :mod:`wear.laws`. A new law is a module declaring a :class:`wear.laws.declaration.Law` and one line here; what
takes a law by name reads it through :func:`law_named`, :func:`parts_of`, :func:`wear_keys` and
:func:`closed_form_laws`.
"""

from __future__ import annotations

from wear.laws import combined, deformation, dnv, finnie, local, oka
from wear.laws.declaration import Constants, Law

__all__ = ["LAWS", "closed_form_laws", "law_named", "parts_of", "wear_keys"]

#: The wear laws by name, in the order of the case key's choices.
LAWS: dict[str, Law] = {
    law.name: law for law in (local.LAW, finnie.LAW, deformation.LAW, combined.LAW, oka.LAW, dnv.LAW)
}


def law_named(name: str) -> Law:
    """The law ``name`` of :data:`LAWS`, or a one-line ``ValueError`` listing them."""
    if name not in LAWS:
        raise ValueError(f"wear.law={name!r} is not a valid choice: must be one of {', '.join(map(repr, LAWS))}")
    return LAWS[name]


def parts_of(name: str, constants: Constants) -> tuple[Law, ...]:
    """The laws the law ``name`` adds up with its ``constants`` (the combined law's cutting law and deformation), or
    the law itself."""
    law = law_named(name)
    return (law,) if law.parts is None else law.parts(constants)


def wear_keys(name: str, constants: Constants) -> tuple[str, ...]:
    """The ``[wear]`` keys the law ``name`` reads with its ``constants``: ``law``, its own constants and inputs, and
    those of the laws it is made of."""
    law = law_named(name)
    keys = ["law", *law.constants, *law.inputs]
    for part in () if law.parts is None else law.parts(constants):
        keys += [k for k in (*part.constants, *part.inputs) if k not in keys]
    return tuple(keys)


def closed_form_laws() -> tuple[str, ...]:
    """The laws whose volume is a formula of the particle's mass, speed and angle and the plate's properties: they
    need no simulated impact."""
    return tuple(name for name, law in LAWS.items() if law.closed_form is not None)
