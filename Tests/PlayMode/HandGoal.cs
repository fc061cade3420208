#if UNITY_EDITOR
#nullable enable
using UnityEngine;

namespace DeltaInterpolator.Tests.PlayMode
{
    /// <summary>The controller's IK pass at work: puts the left hand on <see cref="Goal"/> in every <c>OnAnimatorIK</c> (its layer needs the IK pass on).</summary>
    public sealed class HandGoal : MonoBehaviour
    {
        /// <summary>Where the left hand is put (world).</summary>
        public Vector3 Goal;

        /// <summary>False until the test sets <see cref="Goal"/>.</summary>
        public bool Active;

        private void OnAnimatorIK(int layerIndex)
        {
            if (!Active) return;
            Animator animator = GetComponent<Animator>();
            animator.SetIKPositionWeight(AvatarIKGoal.LeftHand, 1f);
            animator.SetIKPosition(AvatarIKGoal.LeftHand, Goal);
        }
    }
}
#endif
