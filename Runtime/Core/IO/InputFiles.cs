using System.IO;

namespace AvatarGo.Core
{
    // What the file readers check before opening a path.
    internal static class InputFiles
    {
        // A folder given where a file is read: the runtime says "Access to the path ... is denied", a permission problem
        // that is not there.
        internal static void ThrowIfFolder(string path)
        {
            if (path != null && Directory.Exists(path)) throw new IOException($"{path} is a folder, not a file.");
        }
    }
}
