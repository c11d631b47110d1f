"""Writes the explorer page: web/page/explorer.html with its style, script and
the WebAssembly module (emscripten's single-file JavaScript, base64 so that no
sequence in it can end the script element) filled in. Written whole or not at
all. Usage: assemble_page.py MODULE.js PAGE_DIR OUT.html"""
import base64
import os
import sys
import tempfile


def main(module_path, page_dir, out_path):
    def read(name):
        with open(os.path.join(page_dir, name), encoding="utf-8") as f:
            return f.read()

    page = read("explorer.html")
    script = read("explorer.js")
    if "</script" in script.lower():
        sys.exit("assemble_page: explorer.js contains '</script', which would end its element")
    with open(module_path, "rb") as f:
        module = base64.b64encode(f.read()).decode("ascii")
    for marker, text in (("/*@STYLE@*/", read("explorer.css")), ("/*@MODULE_BASE64@*/", module),
                         ("/*@SCRIPT@*/", script)):
        if page.count(marker) != 1:
            sys.exit(f"assemble_page: explorer.html must hold {marker} once")
        page = page.replace(marker, text)
    folder = os.path.dirname(os.path.abspath(out_path))
    os.makedirs(folder, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=folder, prefix=".explorer-", suffix=".html")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(page)
        os.chmod(tmp, 0o644)
        os.replace(tmp, out_path)
    except BaseException:
        os.unlink(tmp)
        raise


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
