#!/usr/bin/env python3
"""Writes a Unity .meta (fresh random GUID, importer matching the file kind) for every package file
and folder that lacks one. Never touches an existing .meta. Skips `~` folders and dot entries, which
Unity does not import, except the contents of each sample (Samples~/NAME/...), which the Package
Manager copies into Assets with their .meta files (a sample scene refers to its scripts by GUID).
Usage: python3 "Tools~/make-metas.py" [package-root]"""
import os, sys, uuid

ROOT_ENTRIES = {'package.json', 'README.md', 'CHANGELOG.md', 'LICENSE.md', 'Third Party Notices.md',
                'Runtime', 'Editor', 'Tests'}

TAIL = "  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n"

def importer(path):
    if os.path.isdir(path):
        return "folderAsset: yes\nDefaultImporter:\n" + TAIL
    name = os.path.basename(path)
    ext = os.path.splitext(name)[1].lower()
    if name == 'package.json':
        return "PackageManifestImporter:\n" + TAIL
    if ext == '.cs':
        return ("MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n"
                "  executionOrder: 0\n  icon: {instanceID: 0}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n")
    if ext == '.asmdef':
        return "AssemblyDefinitionImporter:\n" + TAIL
    if ext == '.prefab':
        return "PrefabImporter:\n" + TAIL
    if ext == '.asmref':
        return "AssemblyDefinitionReferenceImporter:\n" + TAIL
    if ext in ('.md', '.txt', '.json', '.xml', '.csv', '.bytes', '.bvh', '.html', '.yaml', '.yml'):
        return "TextScriptImporter:\n" + TAIL
    return "DefaultImporter:\n" + TAIL

def walk(root, top, only):
    """Yields (folder, dirs, files) under top as os.walk does, skipping what Unity never imports."""
    for d, dirs, files in os.walk(top):
        rel = os.path.relpath(d, top)
        dirs[:] = sorted(x for x in dirs if not x.endswith('~') and not x.startswith('.')
                         and x not in ('bin', 'obj'))
        if rel == '.' and only is not None:
            dirs[:] = [x for x in dirs if x in only]
            files = [x for x in files if x in only]
        yield d, dirs, files

def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..'))
    written = 0
    tops = [(root, ROOT_ENTRIES)]
    samples = os.path.join(root, 'Samples~')
    if os.path.isdir(samples):
        tops += [(os.path.join(samples, n), None) for n in sorted(os.listdir(samples))
                 if os.path.isdir(os.path.join(samples, n)) and not n.startswith('.') and not n.endswith('~')]
    for d, dirs, files in (entry for top, only in tops for entry in walk(root, top, only)):
        for n in sorted(files + dirs):
            if n.endswith('.meta') or n.startswith('.'):
                continue
            path = os.path.join(d, n)
            meta = path + '.meta'
            if os.path.exists(meta):
                continue
            with open(meta, 'w', newline='\n') as f:
                f.write("fileFormatVersion: 2\nguid: %s\n%s" % (uuid.uuid4().hex, importer(path)))
            written += 1
            print("wrote", os.path.relpath(meta, root))
    print(f"{written} .meta file(s) written")

if __name__ == '__main__':
    main()
