using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// A stand-in for a Unity transform hierarchy: nodes with local position, rotation and (uniform or not) scale, whose
    /// world poses follow Unity's rules (a child's position is scaled by its parent's world scale, rotations compose). Built
    /// from a mocap skeleton the way an imported FBX looks: the avatar's root, a mesh object beside the bones, and an
    /// "Armature" node with a rotation and a scale (Blender exports put 100 or 0.01 there) above the hips.
    /// </summary>
    public sealed class EngineHierarchy
    {
        public readonly List<string> Names = new List<string>();
        public readonly List<int> Parents = new List<int>();
        public readonly List<Vector3> LocalPositions = new List<Vector3>();
        public readonly List<Quaternion> LocalRotations = new List<Quaternion>();
        public readonly List<Vector3> LocalScales = new List<Vector3>();

        /// <summary>The node of each humanoid bone, or -1 (what Animator.GetBoneTransform gives).</summary>
        public readonly int[] BoneNodes = new int[HumanoidBones.Count];

        public int Add(string name, int parent, Vector3 position, Quaternion rotation, float scale = 1f)
        {
            Names.Add(name);
            Parents.Add(parent);
            LocalPositions.Add(position);
            LocalRotations.Add(rotation);
            LocalScales.Add(new Vector3(scale));
            return Names.Count - 1;
        }

        /// <summary>The mocap skeleton under root / Armature (rotated and scaled), with a mesh node beside it.</summary>
        public static EngineHierarchy FromSkeleton(HumanoidMap map, Quaternion armatureRotation, float armatureScale)
        {
            var h = new EngineHierarchy();
            for (int b = 0; b < h.BoneNodes.Length; b++) h.BoneNodes[b] = -1;
            int root = h.Add("Avatar", -1, Vector3.Zero, Quaternion.Identity);
            h.Add("Body", root, Vector3.Zero, Quaternion.Identity);
            int armature = h.Add("Armature", root, new Vector3(0f, 0f, 0.01f), armatureRotation, armatureScale);
            Skeleton s = map.Skeleton;
            int first = h.Names.Count;
            Quaternion inverse = Quaternion.Conjugate(armatureRotation);
            for (int j = 0; j < s.JointCount; j++)
            {
                RigidPose rest = s.GetRestLocal(j);
                int parent = s.GetParent(j);
                if (parent < 0)
                    h.Add(s.GetName(j), armature, Vector3.Transform((rest.Position - new Vector3(0f, 0f, 0.01f)) / armatureScale, inverse), inverse * rest.Rotation);
                else
                    h.Add(s.GetName(j), first + parent, rest.Position / armatureScale, rest.Rotation);
            }
            for (int b = 0; b < HumanoidBones.Count; b++)
                if (map[(HumanoidBone)b] >= 0) h.BoneNodes[b] = first + map[(HumanoidBone)b];
            return h;
        }

        public HierarchyNode[] Read()
        {
            var nodes = new HierarchyNode[Names.Count];
            for (int i = 0; i < nodes.Length; i++) nodes[i] = new HierarchyNode(Names[i], Parents[i], LocalPositions[i], LocalRotations[i], LocalScales[i]);
            return nodes;
        }

        /// <summary>The world pose and (uniform) world scale of node <paramref name="i"/>, Unity's way.</summary>
        public void World(int i, out Vector3 position, out Quaternion rotation, out float scale)
        {
            if (Parents[i] < 0)
            {
                position = LocalPositions[i];
                rotation = LocalRotations[i];
                scale = LocalScales[i].X;
                return;
            }
            World(Parents[i], out Vector3 pp, out Quaternion pr, out float ps);
            position = pp + Vector3.Transform(LocalPositions[i] * ps, pr);
            rotation = Quaternion.Normalize(pr * LocalRotations[i]);
            scale = ps * LocalScales[i].X;
        }

        public Vector3 WorldPosition(int i)
        {
            World(i, out Vector3 p, out _, out _);
            return p;
        }

        public Quaternion WorldRotation(int i)
        {
            World(i, out _, out Quaternion r, out _);
            return r;
        }
    }
}
