using System;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    // source: unity:Editor/Mono/EditorGUILayout.cs
    public sealed partial class EditorGUILayout
    {
        public static Object ObjectField(string label, Object obj, Type objType, bool allowSceneObjects, params GUILayoutOption[] options) => throw null!;

        public static Enum EnumPopup(string label, Enum selected, params GUILayoutOption[] options) => throw null!;

        public static float FloatField(string label, float value, params GUILayoutOption[] options) => throw null!;

        public static bool Toggle(string label, bool value, params GUILayoutOption[] options) => throw null!;

        public static int IntField(string label, int value, params GUILayoutOption[] options) => throw null!;

        public static float Slider(string label, float value, float leftValue, float rightValue, params GUILayoutOption[] options) => throw null!;

        public static void HelpBox(string message, MessageType type) => throw null!;
    }
}
