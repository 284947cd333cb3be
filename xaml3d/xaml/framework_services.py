"""The reader's services to the framework step (``xaml3d.framework.services.Services``):
resource look-up with the document's scoping and located diagnostics."""

from __future__ import annotations


class ReaderServices:
    """``Services`` over a ReadContext and the document's Resources."""

    def __init__(self, ctx, resources) -> None:
        self.ctx = ctx
        self.resources = resources

    def lookup(self, key: str, from_el, attr: str | None = None):
        return self.resources.lookup(key, from_el, attr=attr)

    def diag(self, code: str, message: str, el=None, attr: str | None = None, once=None) -> None:
        self.ctx.diag(code, message, el, attr=attr, once=once)

    def find(self, key: str, from_el):
        return self.resources.find(key, from_el)

    def pin_positions(self, root) -> None:
        for el in root.iter():
            if isinstance(el.tag, str):
                self.ctx.locate(el)
